// Precompiled for the test files (Makefile, TEST_PCH): what they all include
// first, as helpers.hpp and test_main.cpp include it, and helpers.hpp itself
// (course/game.hpp, so the engine's headers), which every test file but
// test_main.cpp includes (test_main.cpp is compiled without it).
#define BOOST_TEST_DYN_LINK
#include <boost/test/unit_test.hpp>

#include "helpers.hpp"
