#!/bin/sh
# `make exercise-check`: the exercise tree, built on its own, against the
# per-question suites (q<n>_*), both ways.
#  1. every answer stubbed: every question's suites fail;
#  2. in the sheet's order, questions 1..n answered and the rest stubbed
#     (n = 1..9, incremental rebuilds): the suites of 1..n pass, those of
#     n+1 fail (so each stub alone fails its suite, and no suite needs a
#     later question). n = 9 is the whole tree, answers kept, built alone.
#     These builds make warnings errors (WERROR=1): the stubs compile clean.
#  3. a half-written answer (an unused variable in Q6) still builds, with
#     its warning: the student's tree keeps warnings but not as errors.
#  4. the project's own test binary passes every q<n>_* suite.
#  5. the game of `make exercise-run` runs the tree's course code: built on
#     the stubbed tree, the questions' built-in scenes (built by the course's
#     functions, --course, as exercise-run does) end otherwise than in the
#     project's game; on the answered tree, bit for bit as in it.
# Steps 1-3 need nothing of the project's build but what --reuse names, so
# `make test` runs them beside it (`--trees`); steps 4-5 wait for the test
# binary and the game (`--main`; the game is the one beside the test binary).
# --reuse OBJDIR OBJECT...: objects of the project's build (OBJDIR/x/y.o, of
# x/y.cpp) that the tree's build may take instead of compiling its own copy
# of x/y.cpp: each is copied into the tree's build/obj/ (so its make finds
# it up to date) only where the tree's x/y.cpp is the project's, byte for
# byte (the engine's files and the tests, never a course file: those hold
# the answers). Those objects keep the project's flags (the engine's -O2,
# the tests' -O1), the tree's own are -O0: the same bits at any -O. Every
# course file is still compiled in the tree by its own Makefile, with
# WERROR=1 then without, and the tree's test binary linked there.
# usage: [EXERCISE_OPT=-O0] check.sh --trees DIR [--reuse OBJDIR OBJECT...]
#        check.sh --main MAIN_TESTS_BINARY DIR
set -eu
what=$1
reuse_dir=""
if [ "$what" = --main ]; then main_tests=$2; dir=$3; else
  dir=$2; shift 2
  if [ "${1:-}" = --reuse ]; then reuse_dir=${2%/}; shift 2; fi
  reuse="$*"
fi
gen=tools/exercise/make_exercise.py
MAKE=${MAKE:-make}
fail=0
log=$dir.log
# Builds the tree with the answers of $1 (e.g. "1 2 3") kept, runs its tests,
# prints the per-suite lines ("  ok   q6_mdiff: 2 passed" / "  FAIL ...").
run() {
  python3 "$gen" --out "$dir" --force --keep "$1" >/dev/null
  seed
  $MAKE --no-print-directory -s -C "$dir" build/tests WERROR=1 ${EXERCISE_OPT:+OPT=$EXERCISE_OPT}
  # A stub must never hang a test: bounded.
  (cd "$dir" && BOOST_TEST_COLOR_OUTPUT=no timeout 300 ./build/tests) >"$log" 2>&1 || true
  grep -E '^  (ok  |FAIL) q[0-9]+_' "$log" || { echo "exercise-check: no suite ran (see $log)" >&2; tail -5 "$log" >&2; exit 1; }
}
# Copies the --reuse objects whose source the tree holds unchanged, when
# newer than the tree's own object (or it has none).
seed() {
  [ -n "$reuse_dir" ] || return 0
  for o in $reuse; do
    rel=${o#"$reuse_dir"/}
    src=${rel%.o}.cpp
    [ -f "$dir/$src" ] && cmp -s "$dir/$src" "$src" || continue
    to=$dir/build/obj/$rel
    if [ ! -e "$to" ] || [ "$o" -nt "$to" ]; then
      mkdir -p "$(dirname "$to")"
      cp "$o" "$to"
    fi
  done
}
# expect LINES q STATE: every suite of question q is in STATE (ok or FAIL), and there is one.
expect() {
  suites=$(printf '%s\n' "$1" | grep -E "^  (ok  |FAIL) q$2_" || true)
  if [ -z "$suites" ]; then echo "  Q$2: no suite q$2_*"; fail=1; return; fi
  bad=$(printf '%s\n' "$suites" | grep -v "^  $3" || true)
  if [ -n "$bad" ]; then echo "  Q$2 [$4]: expected $3:"; printf '%s\n' "$bad"; fail=1; fi
}

# viewer KEEP same|differ: the exercise game on a tree with the answers of
# KEEP, against the project's game, on each question's built-in scene.
viewer() {
  vdir=$dir-run
  python3 "$gen" --out "$vdir" --force --keep "$1" >/dev/null
  $MAKE --no-print-directory -s exercise-game EXERCISE="$vdir" >"$vdir.log" 2>&1 ||
    { echo "  exercise-run's game does not build (see $vdir.log)"; fail=1; return; }
  game=$(dirname "$main_tests")/game
  for s in walls drift impulse bounce many; do
    "$vdir/build/run/game" --course --scene $s --headless --frames 60 --dump "$vdir/$s.csv" >/dev/null
    "$game" --course --scene $s --headless --frames 60 --dump "$vdir/$s.main.csv" >/dev/null
    if cmp -s "$vdir/$s.csv" "$vdir/$s.main.csv"; then got=same; else got=differ; fi
    [ $got = "$2" ] || { echo "  exercise-run, answers '$1', scene $s: expected the project's dump to $2"; fail=1; }
  done
  if [ "$2" = same ]; then how="is the project's game's, bit for bit"; else how="differs from the project's game's"; fi
  echo "exercise-check: exercise-run's game, answers '${1:-none}': each question's scene's dump $how"
}

if [ "$what" = --main ]; then
  log=$dir.main.log
  echo "exercise-check: the project's tests ($main_tests), suites q*"
  BOOST_TEST_COLOR_OUTPUT=no "$main_tests" --run_test='q*' >"$log" 2>&1 || { echo "  the project's q suites fail (see $log)"; fail=1; }
  tail -1 "$log"
  viewer "" differ
  viewer "1 2 3 4 5 6 7 8 9" same
  if [ $fail = 0 ]; then echo "exercise-check: ok"; else echo "exercise-check: FAILED"; fi
  exit $fail
fi

echo "exercise-check: every answer stubbed"
out=$(run "")
for q in 1 2 3 4 5 6 7 8 9; do expect "$out" $q FAIL "all stubbed"; done
printf '%s\n' "$out" | sed 's/^/    /'

keep=""
for n in 1 2 3 4 5 6 7 8 9; do
  keep="$keep $n"
  out=$(run "$keep")
  for q in $keep; do expect "$out" $q ok "answers 1..$n"; done
  [ $n -lt 9 ] && expect "$out" $((n + 1)) FAIL "answers 1..$n"
  echo "exercise-check: answers 1..$n: $(tail -1 "$log")"
done
# A half-written answer: a variable not used yet. Built as the student builds
# (no WERROR): a warning, and the tests still run.
rect=$dir/src/course/utils/rect.cpp
sed -i 's|^\( *\)// Q6 begin$|&\n\1int half_written = 0;|' "$rect"
grep -q 'int half_written = 0;' "$rect" || { echo "  cannot insert the half-written answer in $rect"; fail=1; }
if $MAKE --no-print-directory -s -C "$dir" build/tests ${EXERCISE_OPT:+OPT=$EXERCISE_OPT} >"$dir.warn.log" 2>&1 &&
   grep -q "unused variable .half_written" "$dir.warn.log"; then
  echo "exercise-check: a half-written answer (an unused variable) builds, with its warning"
else
  echo "  a half-written answer does not build, or without its warning (see $dir.warn.log)"; fail=1
fi
if [ $fail != 0 ]; then echo "exercise-check: FAILED"; fi
exit $fail
