#pragma once
// Graded tests: the only test header that knows the Catch version (v2 or v3, after
// FMBD_CATCH2_MAJOR from the top-level CMakeLists.txt), together with catch_main.cpp. Test files include this header, never <catch2/...> directly.
//
//   GRADED_TEST("revolute joint: C_q matches finite differences", "[M01][T2][points=2]")
//
// Tags: [Mnn] module, [Tk] task, [points=p] weight. Tests compiled from a module's
// hidden/ folder get the [hidden] tag automatically (FMBD_HIDDEN_TESTS is defined there).

#if FMBD_CATCH2_MAJOR >= 3
#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers.hpp>
using Catch::Approx;  // unqualified, as in v2
#else
#include <catch2/catch.hpp>
#endif

#include <Eigen/Core>

#include <cctype>
#include <exception>
#include <stdexcept>
#include <sstream>
#include <string>
#include <utility>

#include "hint_gate.hpp"
#include "oracles.hpp"

#ifdef FMBD_HIDDEN_TESTS
#define FMBD_VISIBILITY_TAG "[hidden]"
#else
#define FMBD_VISIBILITY_TAG ""
#endif

#define GRADED_TEST(name, tags) TEST_CASE(name, tags FMBD_VISIBILITY_TAG)

// Compare two Eigen objects entrywise with |a - e| <= atol + rtol |e|. On failure Catch prints
// `hint` (the likely mistake) first, then the worst entry with both values. A hint that holds a
// formula passes it through testing::with_formula (hint_gate.hpp).
#define CHECK_CLOSE(actual, expected, tolerance, hint)                                          \
  FMBD_CHECK_COMPARISON(::fmbd::testing::compare((actual), (expected), (tolerance)),           \
                        ::fmbd::testing::quantity_label(#actual), hint)

// Same for scalars.
#define CHECK_NEAR(actual, expected, tolerance, hint)                                            \
  FMBD_CHECK_COMPARISON(::fmbd::testing::compare(::fmbd::testing::as_matrix(actual),             \
                                                 ::fmbd::testing::as_matrix(expected), (tolerance)), \
                        ::fmbd::testing::quantity_label(#actual), hint)

// The same two, with `name` for the compared quantity as the module README names it ("q_ddot of
// forward_dynamics") where the test's own expression would name a variable the student cannot see.
#define CHECK_CLOSE_NAMED(name, actual, expected, tolerance, hint) \
  FMBD_CHECK_COMPARISON(::fmbd::testing::compare((actual), (expected), (tolerance)), name, hint)
#define CHECK_NEAR_NAMED(name, actual, expected, tolerance, hint)                                 \
  FMBD_CHECK_COMPARISON(::fmbd::testing::compare(::fmbd::testing::as_matrix(actual),             \
                                                 ::fmbd::testing::as_matrix(expected), (tolerance)), \
                        name, hint)

#define FMBD_CHECK_COMPARISON(comparison, label, hint)                   \
  do {                                                                   \
    const ::fmbd::testing::Comparison fmbd_cmp_ = (comparison);          \
    INFO("hint: " << (hint));                                            \
    INFO(label << ": " << fmbd_cmp_.report);                             \
    CHECK(fmbd_cmp_.ok);                                                 \
  } while (false)

namespace fmbd::testing {

/// The label of a compared quantity: the test's expression, but for a field of a result that a
/// test holds in a short local variable ("b.M_bar", "a.qdd(2)", "rb->centroid"), which the student
/// cannot see: "your M_bar", "your qdd(2)", "your centroid", the field as the header names it.
inline std::string quantity_label(const std::string& expression) {
  std::size_t letters = 0;
  while (letters < expression.size() && std::islower(static_cast<unsigned char>(expression[letters]))) ++letters;
  if (letters == 0 || letters > 3) return expression;
  const std::size_t arrow = expression.compare(letters, 2, "->") == 0 ? 2 : 0;
  const std::size_t field = letters + (arrow != 0 ? arrow : expression.compare(letters, 1, ".") == 0 ? 1 : 0);
  if (field == letters || field >= expression.size() || !std::isalpha(static_cast<unsigned char>(expression[field])))
    return expression;
  return "your " + expression.substr(field);
}

/// Matches an exception whose what() contains `fragment`, ignoring case.
#if FMBD_CATCH2_MAJOR >= 3
class MessageMentions : public Catch::Matchers::MatcherBase<std::exception> {
#else
class MessageMentions : public Catch::MatcherBase<std::exception> {
#endif
 public:
  explicit MessageMentions(std::string fragment) : fragment_(std::move(fragment)) {}
  bool match(const std::exception& e) const override {
    auto lower = [](std::string s) {
      for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return s;
    };
    return lower(e.what()).find(lower(fragment_)) != std::string::npos;
  }
  std::string describe() const override { return "has a message mentioning \"" + fragment_ + "\""; }

 private:
  std::string fragment_;
};

/// Runs `f` and requires it to throw `Exception` whose message contains `fragment`
/// (case-insensitive); prints `hint` (the likely mistake) on failure. Other exceptions, such as
/// NotImplemented, propagate and fail the test with their own message.
template <typename Exception, typename F>
void check_throws_mentioning(F&& f, const std::string& fragment, const std::string& hint) {
  bool thrown = false;
  std::string message;
  try {
    f();
  } catch (const Exception& e) {
    thrown = true;
    message = e.what();
  }
  INFO("hint: " << hint);
  INFO("expected an exception mentioning \"" << fragment << "\"");
  CHECK(thrown);
  if (!thrown) return;
  CAPTURE(message);
  CHECK(MessageMentions(fragment).match(std::runtime_error(message)));
}

}  // namespace fmbd::testing

// Run `expression` and require it to throw exception type `type` whose message
// contains `fragment` (case-insensitive).
#define CHECK_THROWS_MENTIONING(expression, type, fragment) \
  CHECK_THROWS_MATCHES(expression, type, ::fmbd::testing::MessageMentions(fragment))
