#!/bin/sh
# `make exercise-run` without a display: where each body of the scene starts
# and ends, from two --dump files (id,x,y,w,h,vx,vy,mass), so that the
# student sees without a window whether their blocks move.
# usage: moves.sh START.csv END.csv FRAMES
set -eu
awk -F, -v frames="$3" '
  FNR == 1 { next }
  NR == FNR { start[$1] = "(" $2 ", " $3 ")"; next }
  !printed++ { printf "%-5s %-9s %-6s %-22s %s\n", "body", "size", "mass", "frame 0 (x, y)", "frame " frames " (x, y)" }
  { printf "%-5s %-9s %-6s %-22s (%s, %s)%s\n", $1, $4 "x" $5, $8, ($1 in start ? start[$1] : "-"), $2, $3,
           ($8 != "inf" && start[$1] == "(" $2 ", " $3 ")" ? "   did not move" : "") }
  END { if (!printed) print "no body at all (Q1: the walls are made by Game::init_walls)" }
' "$1" "$2"
