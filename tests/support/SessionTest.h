// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// A fixture for tests that draw: Q3 is initialised for each test and left
// after it, and every error Q3 posts in between is counted; the test fails
// if there was any. Base is the GoogleTest fixture to derive from
// (::testing::Test, or ::testing::TestWithParam<T> for parameterised tests).
// A fixture that overrides SetUp or TearDown calls these first and last.

#include "QD3D.h"
#include "QD3DErrors.h"

#include <gtest/gtest.h>

namespace q3test {

template <class Base = ::testing::Test>
class SessionTest : public Base {
protected:
    void SetUp() override
    {
        ASSERT_EQ(Q3Initialize(), kQ3Success);
        Q3Error_Register(&onError, 0);
        errors() = 0;
    }
    void TearDown() override
    {
        EXPECT_EQ(errors(), 0) << "Q3 posted errors while drawing";
        Q3Error_Register(nullptr, 0);
        Q3Exit();
    }

    /// The errors posted since SetUp.
    static int& errors()
    {
        static int count = 0;
        return count;
    }

private:
    static void onError(TQ3Error, TQ3Error, long) { ++errors(); }
};

} // namespace q3test
