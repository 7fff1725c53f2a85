// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// QD3DMath.h's bounding boxes and spheres as plain values. An empty bound
// (isEmpty any nonzero value, as a C caller may store it) holds nothing and
// its other fields are ignored; the empty bound made here has every other
// field 0. Computed in double; every bound made from points or other bounds
// is rounded outwards, so that it holds every point it was made of exactly,
// not just to within a rounding.
//
// Boxes take each coordinate's least and greatest value, NaN if any was
// NaN. A sphere around points is centred on their box with the radius
// reaching the farthest point: never smaller than the smallest enclosing
// sphere's radius, at most sqrt(3) times it (Ritter, "An Efficient Bounding
// Sphere", Graphics Gems, 1990, discusses both). Two spheres merge into the
// smallest sphere holding both, centred on the line through their centres.

#include "QD3D.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>

namespace q3::math {

/// The largest float not above value, and the smallest not below it.
float roundDown(double value);
float roundUp(double value);

TQ3BoundingBox emptyBox();
/// isEmpty by reference: it may hold any int a C caller stored (core/EnumValue.h).
TQ3BoundingBox makeBox(const TQ3Point3D& min, const TQ3Point3D& max, const TQ3Boolean& isEmpty);
bool isEmpty(const TQ3BoundingBox& box);
TQ3BoundingBox unite(const TQ3BoundingBox& b1, const TQ3BoundingBox& b2);
TQ3BoundingBox unite(const TQ3BoundingBox& box, const glm::dvec3& point);
/// The box of count points, point(i) giving the i-th; empty for none.
TQ3BoundingBox boxOf(std::size_t count, const std::function<glm::dvec3(std::size_t)>& point);

TQ3BoundingSphere emptySphere();
TQ3BoundingSphere makeSphere(const TQ3Point3D& origin, float radius, const TQ3Boolean& isEmpty);
bool isEmpty(const TQ3BoundingSphere& sphere);
/// The smallest sphere holding both (a negative radius is taken as it is).
TQ3BoundingSphere unite(const TQ3BoundingSphere& s1, const TQ3BoundingSphere& s2);
TQ3BoundingSphere unite(const TQ3BoundingSphere& sphere, const glm::dvec3& point);
/// The sphere of count points, point(i) giving the i-th; empty for none.
TQ3BoundingSphere sphereOf(std::size_t count, const std::function<glm::dvec3(std::size_t)>& point);

} // namespace q3::math
