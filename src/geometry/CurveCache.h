// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace q3 {

namespace nurbs {
class BezierForm;
}

/// What a retained NURB curve keeps between renders. The view fills it and
/// decides when it is stale (key: everything the tessellation depends on);
/// the curve empties it on every edit. Immediate-mode curves have none.
struct CurveCache {
    /// The curve's spans in rational Bezier form, built on first use; stays null
    /// for a curve above nurbs::kWholeFormLimit.
    std::shared_ptr<const nurbs::BezierForm> bezier;
    /// What the polyline was made under (edit index, style, matrices, pane...).
    std::vector<double> key;
    /// The last tessellation, x y z per vertex, in the curve's local space.
    std::vector<float> polyline;
    bool valid = false;
    /// Whether building the polyline gave in to the segment cap; a reuse of
    /// the polyline posts the same warning again.
    bool capped = false;
    /// How many times the polyline has been (re)built; tests read it.
    std::uint64_t tessellations = 0;

    void invalidate()
    {
        bezier.reset();
        key.clear();
        polyline.clear();
        valid = false;
        capped = false;
    }
};

} // namespace q3
