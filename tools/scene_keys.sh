#!/bin/sh
# Writes docs/scenes.md's key tables from src/scene/keys.cpp (the test
# scene_keys/the_docs_key_tables_are_the_generated_ones checks them).
# Usage: tools/scene_keys.sh  (after make build/tests)
set -e
cd "$(dirname "$0")/.."
SCENE_KEYS_WRITE=1 ./build/tests --run_test=scene_keys/the_docs_key_tables_are_the_generated_ones
