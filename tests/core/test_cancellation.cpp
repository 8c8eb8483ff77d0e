// Cancellation tokens (frictionlab/cancellation.hpp): which token the work on a thread sees.
#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

#include "frictionlab/cancellation.hpp"

namespace fl = frictionlab;

TEST(Cancellation, NoTokenMeansNeverCancelled) {
  EXPECT_EQ(fl::current_cancel_token(), nullptr);
  EXPECT_FALSE(fl::cancel_requested());
  EXPECT_NO_THROW(fl::throw_if_cancelled());
}

TEST(Cancellation, ScopesNestAndRestoreThePreviousToken) {
  fl::CancelToken outer, inner;
  {
    const fl::CancelScope a(&outer);
    EXPECT_EQ(fl::current_cancel_token(), &outer);
    {
      const fl::CancelScope b(&inner);
      EXPECT_EQ(fl::current_cancel_token(), &inner);
      outer.cancel();
      EXPECT_FALSE(fl::cancel_requested());  // the inner token rules inside its scope
    }
    EXPECT_EQ(fl::current_cancel_token(), &outer);
    EXPECT_TRUE(fl::cancel_requested());
    EXPECT_THROW(fl::throw_if_cancelled(), fl::Cancelled);
  }
  EXPECT_EQ(fl::current_cancel_token(), nullptr);
}

TEST(Cancellation, TheTokenIsPerThread) {
  fl::CancelToken token;
  token.cancel();
  const fl::CancelScope scope(&token);
  bool other_sees_it = true;
  std::thread([&] { other_sees_it = fl::cancel_requested(); }).join();
  EXPECT_FALSE(other_sees_it);
  EXPECT_TRUE(fl::cancel_requested());
}

TEST(Cancellation, CancelledIsNotAStdException) {
  // The handlers that turn a failure into a result catch std::exception; a cancellation must
  // pass through them.
  bool caught_as_std = false, caught_as_cancelled = false;
  try {
    try {
      throw fl::Cancelled{};
    } catch (const std::exception&) {
      caught_as_std = true;
    }
  } catch (const fl::Cancelled&) {
    caught_as_cancelled = true;
  }
  EXPECT_FALSE(caught_as_std);
  EXPECT_TRUE(caught_as_cancelled);
}
