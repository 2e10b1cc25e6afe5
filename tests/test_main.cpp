// The single Boost.Test executable: every C++ test file links into it (MATH §3e).
#define BOOST_TEST_MODULE gmcc
#include <boost/test/unit_test.hpp>
