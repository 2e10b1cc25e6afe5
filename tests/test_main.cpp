// The single Boost.Test executable: every C++ test file links into it (docs/derivations.md §4.5).
#define BOOST_TEST_MODULE gmcc
#include <boost/test/unit_test.hpp>
