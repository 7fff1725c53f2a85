// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include <atomic>
#include <cstdint>

namespace q3 {

/// What a retained NURB curve keeps of its tessellation: nothing but a count.
/// A retained curve may hold at most 4 times its data (issue 16), and even a
/// 4-point Bezier's 65-vertex polyline (780 bytes) is 8 times its 96 data
/// bytes, so no polyline, Bezier form or key is kept: every pass subdivides
/// the curve again into a scratch buffer owned by the view
/// (view/CurveTessellation.h), which the renderer copies into its batch.
/// Immediate-mode and borrowed curves have none.
struct CurveCache {
    CurveCache() = default;
    CurveCache(const CurveCache& other) : tessellations(other.tessellations.load(std::memory_order_relaxed)) {}
    CurveCache& operator=(const CurveCache& other)
    {
        tessellations.store(other.tessellations.load(std::memory_order_relaxed), std::memory_order_relaxed);
        return *this;
    }

    /// How many times the curve has been subdivided (once per pass that drew
    /// or decomposed it); tests and benchmarks read it. Atomic because views
    /// on several threads may draw the same retained curve.
    std::atomic<std::uint64_t> tessellations{0};
};

} // namespace q3
