// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The round trip of a Set call and its Get, as the API tests check it.

#include "QD3D.h"

#include <gtest/gtest.h>

#include <cstring>

namespace q3test {

/// `set(object, &value)` succeeds and bumps the object's edit index, and
/// `get` then gives `value` back byte for byte.
template <class Object, class T>
void expectSetThenGet(Object object, TQ3Status (*set)(Object, const T*), TQ3Status (*get)(Object, T*),
                      const T& value)
{
    const unsigned long edit = Q3Shared_GetEditIndex(object);
    EXPECT_EQ(set(object, &value), kQ3Success);
    EXPECT_NE(Q3Shared_GetEditIndex(object), edit);
    T out{};
    EXPECT_EQ(get(object, &out), kQ3Success);
    EXPECT_EQ(std::memcmp(&out, &value, sizeof out), 0);
}

} // namespace q3test
