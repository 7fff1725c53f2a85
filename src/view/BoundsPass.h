// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3D.h"
#include "view/Pass.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace q3 {

/// A traversal of a bounding loop: the world-space box and sphere around
/// everything submitted with extent. A geometry counts as the points its
/// bound() gives: a NURB curve its control points projected to 3D (x/w, y/w,
/// z/w), as the article says QuickDraw 3D bounds it; others the vertices they
/// decompose into. Exact mode
/// transforms every point to world space; approximate mode transforms the
/// corners of the shape's local box, which is cheaper and may be larger.
/// Invariant: the box and sphere enclose, in double precision, every world
/// point added so far; both are empty until the first one.
class BoundsPass final : public Pass {
public:
    BoundsPass(TQ3ComputeBounds mode, std::optional<Window> window, const AttributeValues& attributes)
        : Pass(std::move(window), attributes), m_mode(mode)
    {
    }

    void visitGeometry(const Geometry& geometry) override;

    /// The results, rounded outwards to float; isEmpty with zero fields when
    /// nothing was added.
    TQ3BoundingBox box() const;
    TQ3BoundingSphere sphere() const;

protected:
    /// A group's bounding box bounds it: its corners are added.
    bool enterBoundedGroup(const DisplayGroup& group, const TQ3BoundingBox& box) override;

private:
    /// Adds one shape given by its local points (m_local).
    void addShape();

    TQ3ComputeBounds m_mode;
    std::vector<glm::dvec3> m_local;
    std::vector<glm::dvec3> m_world;
    bool m_empty = true;
    glm::dvec3 m_min{0.0};
    glm::dvec3 m_max{0.0};
    glm::dvec3 m_center{0.0};
    double m_radius = 0.0;
};

} // namespace q3
