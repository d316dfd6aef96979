// Precompiled for the test files (Makefile, TEST_PCH): what they all include
// first, as helpers.hpp and test_main.cpp include it.
#define BOOST_TEST_DYN_LINK
#include <boost/test/unit_test.hpp>
