// The one test executable: doctest's main, one TEST_SUITE per module of src/.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
