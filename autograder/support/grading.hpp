#pragma once
// Graded tests: the only test header that knows the Catch version (v2), together with
// catch_main.cpp. Test files include this header, never <catch2/...> directly.
//
//   GRADED_TEST("revolute joint: C_q matches finite differences", "[M01][T2][points=2]")
//
// Tags: [Mnn] module, [Tk] task, [points=p] weight. Tests compiled from a module's
// hidden/ folder get the [hidden] tag automatically (FMBD_HIDDEN_TESTS is defined there).

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <sstream>
#include <string>

#include "oracles.hpp"

#ifdef FMBD_HIDDEN_TESTS
#define FMBD_VISIBILITY_TAG "[hidden]"
#else
#define FMBD_VISIBILITY_TAG ""
#endif

#define GRADED_TEST(name, tags) TEST_CASE(name, tags FMBD_VISIBILITY_TAG)

// Compare two Eigen objects entrywise with |a - e| <= atol + rtol |e|. On failure the
// report names the worst entry, both values, and prints `hint` (the likely mistake).
#define CHECK_CLOSE(actual, expected, tolerance, hint)                                   \
  do {                                                                                   \
    const ::fmbd::testing::Comparison fmbd_cmp_ =                                        \
        ::fmbd::testing::compare((actual), (expected), (tolerance));                     \
    INFO(#actual " vs " #expected ": " << fmbd_cmp_.report);                             \
    INFO("hint: " << (hint));                                                            \
    CHECK(fmbd_cmp_.ok);                                                                 \
  } while (false)

// Same for scalars.
#define CHECK_NEAR(actual, expected, tolerance, hint)                                    \
  CHECK_CLOSE(::fmbd::testing::as_matrix(actual), ::fmbd::testing::as_matrix(expected), \
              tolerance, hint)

// Run `expression` and require it to throw exception type `type` whose message
// contains `fragment` (case-insensitive).
#define CHECK_THROWS_MENTIONING(expression, type, fragment)                              \
  CHECK_THROWS_MATCHES(expression, type,                                                 \
                       Catch::Matchers::Contains(fragment, Catch::CaseSensitive::No))
