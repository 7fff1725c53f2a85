// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The QuickDraw 3D quadrics and solids as parametric patches: plain values in
// (an origin, three vectors, parameter ranges, cap bits), patches out, each a
// map from a parameter rectangle to local space with its outward unit normal
// and surface uv. Tessellate.h turns patches into triangles.
//
// Every shape but the torus is an affine image of a canonical shape in the
// frame x = majorRadius (majorAxis), y = minorRadius (minorAxis),
// z = orientation, so a point is origin + A c for a canonical point c, with
// A = [x y z], and its outward normal is A^-T n for the canonical outward
// normal n (the gradient of the canonical implicit function, pulled back:
// outward whatever the frame's handedness). The canonical shapes, with
// theta = 2 pi u (u in turns, counterclockwise from x towards y):
//   cylinder side   (cos theta, sin theta, v),                 v in [0, 1]
//   cone side       ((1 - v) cos theta, (1 - v) sin theta, v),  apex at v = 1
//   ellipsoid       (sin phi cos theta, sin phi sin theta, -cos phi),
//                   phi = pi v: v = 0 the pole at -z, v = 1 the pole at +z
//   disk            (v cos theta, v sin theta, 0),              v = 0 the centre
//   box             the unit cube [0, 1]^3 (origin a corner)
// The torus (QuickDraw 3D's definition as Quesa draws it) is not affine:
//   P(u, v) = origin + a(theta) - sin(psi) z - cos(psi) k a(theta) / |a(theta)|
// with a(theta) = cos theta x + sin theta y, k = ratio |z|, psi = 2 pi v:
// an ellipse of half-axes |z| (along z) and k (along the ring's radius) swept
// around the ring a(theta); v = 0 is the inner equator, v = 1/4 the bottom.
// Its normal is the cross product of the analytic partial derivatives.
//
// Parts that close a shape (caps, the faces of a cut) are flat; they share
// their curved edges with the side patch, whose rows they reuse (Link), so
// the shape is watertight.

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace q3::quadric {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;

/// QuickDraw 3D's TQ3EndCapMasks, as plain bits.
enum Caps : unsigned { kCapTop = 1, kCapBottom = 2, kCapInterior = 4 };

/// Which attribute set a patch's vertices take (the shape's data names them).
enum Part : int { kPartFace = 0, kPartBottom = 1, kPartTop = 2, kPartInterior = 3 };

/// A parameter range [min, max]. For an angle (in turns) that wraps past 0
/// (QuickDraw 3D's uMin > uMax), max is uMax + 1.
struct Range {
    double min = 0.0;
    double max = 1.0;
    double length() const { return max - min; }
    bool full() const { return max - min >= 1.0; }
};

/// An angular range from QuickDraw 3D's (uMin, uMax): uMin > uMax wraps
/// through angle 0. Both in [0, 1] and not equal (the data rules).
Range angularRange(double min, double max);

/// How the constant subdivision method divides one parameter direction of a
/// patch: ceil(c * span) segments with c the style's c1 (`which` 1) or c2
/// (`which` 2), or one segment (`which` 0: a straight direction), never
/// fewer than `minimum`.
struct ConstantRule {
    int which = 0;
    double span = 1.0;
    unsigned minimum = 1;
};

/// Where a row of a patch takes its u parameters from a patch tessellated
/// before it: that patch's first row, its last row, or the list of its row
/// v values (for a patch whose u runs along the other's v).
struct RowSource {
    enum What { kFirstRow, kLastRow, kRowValues };
    int patch = -1; ///< index of the earlier patch, or -1: none
    What what = kFirstRow;
};

/// How a patch shares its edges with earlier patches: every v row (`rows`:
/// the same v values as that patch), and the u parameters of its first (v0)
/// and last (v1) rows.
struct Link {
    int rows = -1;
    RowSource first;
    RowSource last;
};

/// A patch: a map from [u0, u1] x [v0, v1] to local space. Rows run along u
/// at fixed v. A row whose whole length is one point (a pole, an apex, a
/// centre) is "collapsed".
class Patch {
public:
    virtual ~Patch() = default;
    virtual Vec3 point(double u, double v) const = 0;
    /// The outward unit normal (at a collapsed row: its limit along u).
    virtual Vec3 normal(double u, double v) const = 0;
    /// QuickDraw 3D's surface uv.
    virtual Vec2 uv(double u, double v) const = 0;

    double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
    bool collapsedV0 = false, collapsedV1 = false;
    bool closedU = false; ///< a full turn in u (at least 3 segments)
    bool closedV = false; ///< a full turn in v (at least 3 segments)
    /// How many turns u and v sweep where they are angles (0 where they are
    /// straight): the measured method gives at least one segment per
    /// quarter turn, so that no triangle spans more than a right angle of a
    /// curved surface however large c1 is.
    double turnsU = 0.0, turnsV = 0.0;
    ConstantRule constantU, constantV;
    int part = kPartFace;
    Link link;
};

using Patches = std::vector<std::unique_ptr<Patch>>;

/// A frame: the origin and the three vectors as the columns of A.
struct Frame {
    Vec3 origin{0.0};
    glm::dmat3 axes{1.0};
    glm::dmat3 normals{1.0}; ///< A^-T

    Frame() = default;
    /// x, y, z must be independent (independence() > 0).
    Frame(const Vec3& origin, const Vec3& x, const Vec3& y, const Vec3& z);
    Vec3 point(const Vec3& canonical) const { return origin + axes * canonical; }
    /// The unit normal for a canonical (gradient) normal.
    Vec3 normal(const Vec3& canonical) const;
};

/// |x . (y x z)| over |x| |y| |z|: how far three vectors are from lying in
/// one plane (0 when one is zero or they are coplanar, 1 when orthogonal).
/// Two vectors: |x x y| / (|x| |y|).
double independence(const Vec3& x, const Vec3& y, const Vec3& z);
double independence(const Vec3& x, const Vec3& y);

/// Frames whose independence is at or below this are degenerate (the data
/// rules refuse them): the shape would be flat or a line.
constexpr double kDegenerateFrame = 1e-6;

struct BoxShape {
    Vec3 origin, orientation, majorAxis, minorAxis;
};

/// Cones, cylinders, ellipsoids: a side revolved around the orientation.
struct RevolvedShape {
    Vec3 origin, orientation, majorRadius, minorRadius;
    Range u, v;
    unsigned caps = 0;
};

struct DiskShape {
    Vec3 origin, majorRadius, minorRadius;
    Range u, v;
};

struct TorusShape {
    Vec3 origin, orientation, majorRadius, minorRadius;
    double ratio = 1.0;
    Range u, v;
    unsigned caps = 0;
};

struct EllipseShape {
    Vec3 origin, majorRadius, minorRadius;
    Range u;
};

/// The six faces in QuickDraw 3D's order, part = face index: 0 left (the
/// face at the origin spanned by majorAxis and orientation), 1 right
/// (opposite it), 2 front (the face at the end of majorAxis), 3 back (at the
/// origin, opposite), 4 top (at the end of orientation), 5 bottom. Each face
/// has u and v from 0 to 1, u to the right and v up seen from outside.
Patches boxPatches(const BoxShape& box);

/// The side (kPartFace); with kCapBottom the bottom disk at vMin
/// (kPartBottom); with kCapInterior the faces of a cut (kPartInterior): the
/// top disk at vMax when vMax < 1 and the two faces at uMin and uMax when u
/// is not a full turn. kCapTop is ignored (QD3D book, TQ3ConeData).
Patches conePatches(const RevolvedShape& cone);

/// The side; kCapBottom and kCapTop the disks at vMin (kPartBottom) and vMax
/// (kPartTop); kCapInterior the faces at uMin and uMax when u is not a full
/// turn (kPartInterior).
Patches cylinderPatches(const RevolvedShape& cylinder);

/// The surface; kCapBottom and kCapTop the disks at vMin and vMax when they
/// cut the surface (vMin > 0, vMax < 1); kCapInterior the faces at uMin and
/// uMax (from the axis to the surface) when u is not a full turn. Every cap
/// is kPartInterior (TQ3EllipsoidData has only interiorAttributeSet).
Patches ellipsoidPatches(const RevolvedShape& ellipsoid);

/// The disk, partial in angle (u) and radius (v).
Patches diskPatches(const DiskShape& disk);

/// The surface; with kCapInterior the faces of a cut (kPartInterior): the
/// cross-sections at uMin and uMax when u is not a full turn (the part of
/// the tube's cross-section between its centre and the surface), and when v
/// is not a full turn the two walls from the tube's centre line to the cut
/// edges at vMin and vMax. The solid they close is the set of points
/// centre(u) + s (P(u, v) - centre(u)), s in [0, 1]. kCapTop and kCapBottom
/// mean nothing for a torus and are ignored.
Patches torusPatches(const TorusShape& torus);

/// The ellipse's point at u (turns): origin + cos theta x + sin theta y.
Vec3 ellipsePoint(const EllipseShape& ellipse, double u);

} // namespace q3::quadric
