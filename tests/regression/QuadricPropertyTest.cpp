// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The quadrics and solids as Q3 draws them (the TriMesh of
// Q3Geometry_GetDecomposed in a bounding or rendering loop), checked against
// the shapes as QD3DGeometry.h defines them, evaluated here in long double
// from the header's formulas and sharing no code with src/:
//   - every vertex lies on one part of the shape (side, cap, face of a cut,
//     box face) at the parameters its surface uv names, within the part's
//     parameter range, and its normal is that part's outward unit normal;
//   - partial shapes reach both ends of their ranges, and the caps drawn are
//     exactly those the mask asks for;
//   - triangles are counterclockwise seen from outside;
//   - world space: no triangle edge longer than c1 after the local-to-world
//     transform; screen space: no edge longer than c1 pixels (orthographic
//     and perspective cameras, edges crossing the hither plane measured to
//     it); and the triangle count close to the lower bound
//     drawn area / (sqrt(3)/4 c1^2) (an equilateral triangle of side c1 is
//     the largest with no longer edge);
//   - constant subdivision gives the documented counts; the ellipse is a
//     near-minimal polyline on the ellipse.
// The affine shapes' normals come from the inverse transpose of the frame
// written with cross products; the torus's from central differences of its
// parameterisation, oriented away from the tube's centre line.
//
// Tolerances: a vertex is a float point and its uv floats, which moves it
// by at most 2^-24 of its coordinates plus 2 pi 2^-24 (for u up to 2) of a
// radius: below 1e-6 of the shape's scale (the origin's largest coordinate
// plus the vectors' lengths), kOnShape. Normals are floats: unit and along
// the reference within 1e-5. Edge lengths are compared with c1 (1 + 1e-4)
// (float vertices, against Q3's double arithmetic).

#include "PixmapViewTest.h"
#include "Q3ApiTest.h"
#include "SubdivisionReference.h"

#include "QD3DCamera.h"
#include "QD3DDrawContext.h"
#include "QD3DGeometry.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DView.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace q3test::subdivision;

constexpr unsigned long kWidth = 160;
constexpr unsigned long kHeight = 120;
constexpr unsigned kDefaultSeed = 20260501u;

/// Q3_QUADRIC_SEED if set (to replay or explore other random shapes), else a
/// fixed seed.
unsigned seed()
{
    if (const char* text = std::getenv("Q3_QUADRIC_SEED"))
        return unsigned(std::strtoul(text, nullptr, 10));
    return kDefaultSeed;
}
constexpr Real kOnShape = 1e-6L;
constexpr Real kNormalSlack = 1e-5L;
constexpr Real kEdgeSlack = 1e-4L;
constexpr Real kPi = 3.14159265358979323846264338327950288L;
constexpr int kScenesPerKind = 4;

enum class Kind { kBox, kCone, kCylinder, kDisk, kEllipsoid, kTorus };
const Kind kKinds[] = {Kind::kBox, Kind::kCone, Kind::kCylinder, Kind::kDisk, Kind::kEllipsoid, Kind::kTorus};

const char* nameOf(Kind kind)
{
    switch (kind) {
    case Kind::kBox:
        return "box";
    case Kind::kCone:
        return "cone";
    case Kind::kCylinder:
        return "cylinder";
    case Kind::kDisk:
        return "disk";
    case Kind::kEllipsoid:
        return "ellipsoid";
    case Kind::kTorus:
        return "torus";
    }
    return "?";
}

TQ3Vector3D toVector(const Vec3& v)
{
    return {float(v.x), float(v.y), float(v.z)};
}
Vec3 fromVector(const TQ3Vector3D& v)
{
    return {v.x, v.y, v.z};
}

/// A shape as its data says, in long double (the float values widened).
struct Shape {
    Kind kind = Kind::kBox;
    Vec3 origin, x, y, z; ///< majorRadius (majorAxis), minorRadius (minorAxis), orientation
    Real ratio = 1;
    Real uMin = 0, uMax = 1, vMin = 0, vMax = 1;
    unsigned long caps = 0;

    Real uEnd() const { return uMax > uMin ? uMax : uMax + 1; }
    Real vEnd() const { return vMax > vMin || kind != Kind::kTorus ? vMax : vMax + 1; }
    bool fullU() const { return uMin == 0 && uMax == 1; }
    bool fullV() const { return vMin == 0 && vMax == 1; }
    Real scale() const
    {
        return maxAbs(origin) + norm(x) + norm(y) + norm(z) * (1 + (kind == Kind::kTorus ? ratio : 0));
    }

    /// origin + c.x x + c.y y + c.z z.
    Vec3 at(const Vec3& c) const { return origin + c.x * x + c.y * y + c.z * z; }
    /// The outward normal for a canonical gradient g: A^-T g, A = [x y z],
    /// written as (g.x (y^z) + g.y (z^x) + g.z (x^y)) / det.
    Vec3 normalFor(const Vec3& g) const
    {
        const Real det = dot(x, cross(y, z));
        return unit((1 / det) * (g.x * cross(y, z) + g.y * cross(z, x) + g.z * cross(x, y)));
    }
};

/// Where a vertex sits on the shape, as the reference sees it.
struct Candidate {
    const char* part;
    Vec3 point;
    Vec3 normal;
};

bool within(Real value, Real lo, Real hi, Real slack = 1e-6L)
{
    return value >= lo - slack && value <= hi + slack;
}

/// True when the angle (turns) lies in [uMin, uEnd] modulo whole turns.
bool angleWithin(const Shape& s, Real turns)
{
    for (int k = -1; k <= 2; ++k)
        if (within(turns + k, s.uMin, s.uEnd(), 1e-5L))
            return true;
    return false;
}

// ---- The torus ----------------------------------------------------------------

Vec3 ring(const Shape& s, Real theta)
{
    return std::cos(theta) * s.x + std::sin(theta) * s.y;
}

Vec3 spoke(const Shape& s, Real theta, Real psi)
{
    return -std::sin(psi) * s.z - std::cos(psi) * s.ratio * norm(s.z) * unit(ring(s, theta));
}

Vec3 torusPoint(const Shape& s, Real u, Real v, Real fraction = 1)
{
    const Real theta = 2 * kPi * u, psi = 2 * kPi * v;
    return s.origin + ring(s, theta) + fraction * spoke(s, theta, psi);
}

/// The normal of a map (a, b) -> point by central differences, oriented
/// along `outward`.
Vec3 numericNormal(const std::function<Vec3(Real, Real)>& f, Real a, Real b, const Vec3& outward)
{
    const Real h = 1e-6L;
    const Vec3 da = f(a + h, b) - f(a - h, b), db = f(a, b + h) - f(a, b - h);
    Vec3 n = unit(cross(da, db));
    return dot(n, outward) < 0 ? Real(-1) * n : n;
}

/// Every part of the shape a vertex with surface uv (su, sv) may sit on.
std::vector<Candidate> candidates(const Shape& s, Real su, Real sv)
{
    std::vector<Candidate> out;
    const Real theta = 2 * kPi * su;
    const bool cutU = !s.fullU() && (s.caps & kQ3EndCapMaskInterior);
    // A planar uv (disks, caps, sections): the point's place in the unit
    // square around the disk.
    const Real px = 2 * su - 1, py = 2 * sv - 1, pr = std::hypot(px, py);
    const Real pAngle = std::atan2(py, px) / (2 * kPi);
    const bool planarInRange = pr <= 1 + 1e-5L && (pr < 1e-5L || angleWithin(s, pAngle));
    auto cap = [&](const char* part, Real height, Real radius, Real facing) {
        if (planarInRange)
            out.push_back({part, s.at({radius * px, radius * py, height}), s.normalFor({0, 0, facing})});
    };
    // The faces of a u cut: uv (fraction from the axis, v); profile radius
    // and height at v.
    auto cuts = [&](const std::function<Real(Real)>& radius, const std::function<Real(Real)>& height) {
        if (!cutU || !within(su, 0, 1) || !within(sv, s.vMin, s.vMax))
            return;
        for (const bool atMin : {true, false}) {
            const Real t = 2 * kPi * (atMin ? s.uMin : s.uMax);
            const Vec3 g = atMin ? Vec3{std::sin(t), -std::cos(t), 0} : Vec3{-std::sin(t), std::cos(t), 0};
            const Real r = su * radius(sv);
            out.push_back({"interior", s.at({r * std::cos(t), r * std::sin(t), height(sv)}), s.normalFor(g)});
        }
    };
    const bool sideInRange = within(su, s.uMin, s.uEnd()) && within(sv, s.vMin, s.vEnd());
    switch (s.kind) {
    case Kind::kBox: {
        if (!within(su, 0, 1) || !within(sv, 0, 1))
            break;
        const Real u = su, v = sv;
        // QD3DGeometry.h's faces: left, right, front, back, top, bottom.
        out.push_back({"left", s.at({u, 0, v}), s.normalFor({0, -1, 0})});
        out.push_back({"right", s.at({1 - u, 1, v}), s.normalFor({0, 1, 0})});
        out.push_back({"front", s.at({1, u, v}), s.normalFor({1, 0, 0})});
        out.push_back({"back", s.at({0, 1 - u, v}), s.normalFor({-1, 0, 0})});
        out.push_back({"top", s.at({1 - v, u, 1}), s.normalFor({0, 0, 1})});
        out.push_back({"bottom", s.at({1 - v, 1 - u, 0}), s.normalFor({0, 0, -1})});
        break;
    }
    case Kind::kCone:
        if (sideInRange)
            out.push_back({"face", s.at({(1 - sv) * std::cos(theta), (1 - sv) * std::sin(theta), sv}),
                           s.normalFor({std::cos(theta), std::sin(theta), 1})});
        if (s.caps & kQ3EndCapMaskBottom)
            cap("bottom", s.vMin, 1 - s.vMin, -1);
        if ((s.caps & kQ3EndCapMaskInterior) && s.vMax < 1)
            cap("interior", s.vMax, 1 - s.vMax, 1);
        cuts([](Real v) { return 1 - v; }, [](Real v) { return v; });
        break;
    case Kind::kCylinder:
        if (sideInRange)
            out.push_back({"face", s.at({std::cos(theta), std::sin(theta), sv}),
                           s.normalFor({std::cos(theta), std::sin(theta), 0})});
        if (s.caps & kQ3EndCapMaskBottom)
            cap("bottom", s.vMin, 1, -1);
        if (s.caps & kQ3EndCapMaskTop)
            cap("top", s.vMax, 1, 1);
        cuts([](Real) { return Real(1); }, [](Real v) { return v; });
        break;
    case Kind::kEllipsoid: {
        const Real phi = kPi * sv;
        const Vec3 c{std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), -std::cos(phi)};
        if (sideInRange)
            out.push_back({"face", s.at(c), s.normalFor(c)});
        if ((s.caps & kQ3EndCapMaskBottom) && s.vMin > 0)
            cap("interior", -std::cos(kPi * s.vMin), std::sin(kPi * s.vMin), -1);
        if ((s.caps & kQ3EndCapMaskTop) && s.vMax < 1)
            cap("interior", -std::cos(kPi * s.vMax), std::sin(kPi * s.vMax), 1);
        cuts([](Real v) { return std::sin(kPi * v); }, [](Real v) { return -std::cos(kPi * v); });
        break;
    }
    case Kind::kDisk:
        if (planarInRange && within(pr, s.vMin, s.vMax))
            out.push_back({"face", s.at({px, py, 0}), unit(cross(s.x, s.y))});
        break;
    case Kind::kTorus: {
        if (sideInRange) {
            const Vec3 p = torusPoint(s, su, sv);
            const Vec3 n = numericNormal([&](Real a, Real b) { return torusPoint(s, a, b); }, su, sv,
                                         p - (s.origin + ring(s, theta)));
            out.push_back({"face", p, n});
        }
        if (!(s.caps & kQ3EndCapMaskInterior))
            break;
        if (!s.fullU()) {
            // The cross-sections at uMin and uMax: planar uv around the tube.
            const Real psiTurns = pAngle, fraction = pr;
            const bool inV = fraction < 1e-5L || [&] {
                for (int k = -1; k <= 2; ++k)
                    if (within(psiTurns + k, s.vMin, s.vEnd(), 1e-5L))
                        return true;
                return false;
            }();
            if (fraction <= 1 + 1e-5L && inV)
                for (const bool atMin : {true, false}) {
                    const Real t = atMin ? s.uMin : s.uMax;
                    const Vec3 tangent = ring(s, 2 * kPi * t + kPi / 2);
                    Vec3 n = unit(cross(s.z, ring(s, 2 * kPi * t)));
                    if ((dot(n, tangent) < 0) != atMin)
                        n = Real(-1) * n;
                    out.push_back({"interior", torusPoint(s, t, psiTurns, fraction), n});
                }
        }
        if (!s.fullV() && within(su, s.uMin, s.uEnd()) && within(sv, 0, 1)) {
            // The walls from the centre line to the cut edges: uv (u, fraction).
            for (const bool atMin : {true, false}) {
                const Real psiTurns = atMin ? s.vMin : s.vEnd();
                const Vec3 p = torusPoint(s, su, psiTurns, sv);
                // Outward: against increasing v at vMin, along it at vMax.
                const Vec3 alongV = torusPoint(s, su, psiTurns + 1e-4L) - torusPoint(s, su, psiTurns - 1e-4L);
                const Vec3 n =
                    numericNormal([&](Real a, Real b) { return torusPoint(s, a, psiTurns, b); }, su,
                                  std::clamp(sv, Real(1e-5), Real(1 - 1e-5)), atMin ? Real(-1) * alongV : alongV);
                out.push_back({"interior", p, n});
            }
        }
        break;
    }
    }
    return out;
}

/// The parts a shape's data asks to be drawn.
std::vector<std::string> expectedParts(const Shape& s)
{
    const bool cutU = !s.fullU() && (s.caps & kQ3EndCapMaskInterior);
    switch (s.kind) {
    case Kind::kBox:
        return {"left", "right", "front", "back", "top", "bottom"};
    case Kind::kCone: {
        std::vector<std::string> parts{"face"};
        if (s.caps & kQ3EndCapMaskBottom)
            parts.push_back("bottom");
        if (cutU || ((s.caps & kQ3EndCapMaskInterior) && s.vMax < 1))
            parts.push_back("interior");
        return parts;
    }
    case Kind::kCylinder: {
        std::vector<std::string> parts{"face"};
        if (s.caps & kQ3EndCapMaskBottom)
            parts.push_back("bottom");
        if (s.caps & kQ3EndCapMaskTop)
            parts.push_back("top");
        if (cutU)
            parts.push_back("interior");
        return parts;
    }
    case Kind::kEllipsoid: {
        std::vector<std::string> parts{"face"};
        if (cutU || ((s.caps & kQ3EndCapMaskBottom) && s.vMin > 0) || ((s.caps & kQ3EndCapMaskTop) && s.vMax < 1))
            parts.push_back("interior");
        return parts;
    }
    case Kind::kDisk:
        return {"face"};
    case Kind::kTorus: {
        std::vector<std::string> parts{"face"};
        if ((s.caps & kQ3EndCapMaskInterior) && (!s.fullU() || !s.fullV()))
            parts.push_back("interior");
        return parts;
    }
    }
    return {};
}

// ---- Random shapes --------------------------------------------------------------

Vec3 randomVector(std::mt19937& rng, Real lo, Real hi)
{
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> length{double(lo), double(hi)};
    for (;;) {
        const Vec3 v{normal(rng), normal(rng), normal(rng)};
        if (norm(v) > 1e-3L)
            return Real(length(rng)) * unit(v);
    }
}

/// Rounds to the floats the data holds.
Vec3 asFloat(const Vec3& v)
{
    return fromVector(toVector(v));
}

/// A random shape of the kind. A `regular` one has orthogonal vectors whose
/// lengths differ by at most 2 times (a round or mildly elliptic shape);
/// the others any independent frame with lengths from 0.4 to 2.5.
Shape randomShape(std::mt19937& rng, Kind kind, bool regular = false)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Shape s;
    s.kind = kind;
    s.origin = asFloat(randomVector(rng, 0, 4));
    for (;;) {
        const Real shortest = regular ? 0.8L : 0.4L, longest = regular ? 1.6L : 2.5L;
        s.x = randomVector(rng, shortest, longest);
        s.y = randomVector(rng, shortest, longest);
        s.z = randomVector(rng, shortest, longest);
        if (regular || u(rng) < 0.5 || kind == Kind::kTorus) {
            // An orthogonal frame (the torus: its orientation orthogonal to
            // the ring, as Apple asks), left-handed now and then.
            const Vec3 x = unit(s.x);
            const Vec3 y = unit(s.y - dot(s.y, x) * x);
            s.y = norm(s.y) * y;
            s.z = (u(rng) < 0.3 ? -norm(s.z) : norm(s.z)) * cross(x, y);
            if (kind == Kind::kTorus)
                s.z = Real(regular ? 0.3 + 0.2 * u(rng) : 0.15 + 0.3 * u(rng)) * std::min(norm(s.x), norm(s.y)) *
                      unit(s.z);
        }
        s.x = asFloat(s.x);
        s.y = asFloat(s.y);
        s.z = asFloat(s.z);
        if (std::fabs(dot(s.x, cross(s.y, s.z))) > 0.35L * norm(s.x) * norm(s.y) * norm(s.z))
            break;
    }
    auto unitFloat = [&] { return Real(float(u(rng))); };
    if (kind != Kind::kBox && u(rng) < 0.6) {
        do {
            s.uMin = unitFloat();
            s.uMax = unitFloat();
        } while (std::fabs(s.uMin - s.uMax) < 0.1L);
    }
    if (kind != Kind::kBox && u(rng) < 0.5) {
        do {
            s.vMin = unitFloat();
            s.vMax = unitFloat();
        } while (std::fabs(s.vMin - s.vMax) < 0.1L);
        if (kind != Kind::kTorus && s.vMin > s.vMax)
            std::swap(s.vMin, s.vMax);
    }
    s.caps = (unsigned long)(std::min(7.0, 8 * u(rng)));
    if (kind == Kind::kTorus) {
        // A tube thinner than the ring is narrow, so the tube does not cross
        // itself: ratio |z| below half the ring's smallest radius.
        Real smallest = 1e30L;
        for (int i = 0; i < 64; ++i)
            smallest = std::min(smallest, norm(ring(s, 2 * kPi * i / 64)));
        s.ratio = Real(float(Real(0.2 + 0.3 * u(rng)) * smallest / norm(s.z)));
    }
    return s;
}

/// The data structures, geometry and GetDecomposed for a shape.
TQ3GeometryObject newGeometry(const Shape& s)
{
    const TQ3Point3D o = toPoint(s.origin);
    const TQ3Vector3D x = toVector(s.x), y = toVector(s.y), z = toVector(s.z);
    const float u0 = float(s.uMin), u1 = float(s.uMax), v0 = float(s.vMin), v1 = float(s.vMax);
    switch (s.kind) {
    case Kind::kBox: {
        const TQ3BoxData d{o, z, x, y, nullptr, nullptr};
        return Q3Box_New(&d);
    }
    case Kind::kCone: {
        const TQ3ConeData d{o, z, x, y, u0, u1, v0, v1, s.caps, nullptr, nullptr, nullptr, nullptr};
        return Q3Cone_New(&d);
    }
    case Kind::kCylinder: {
        const TQ3CylinderData d{o, z, x, y, u0, u1, v0, v1, s.caps, nullptr, nullptr, nullptr, nullptr, nullptr};
        return Q3Cylinder_New(&d);
    }
    case Kind::kDisk: {
        const TQ3DiskData d{o, x, y, u0, u1, v0, v1, nullptr};
        return Q3Disk_New(&d);
    }
    case Kind::kEllipsoid: {
        const TQ3EllipsoidData d{o, z, x, y, u0, u1, v0, v1, s.caps, nullptr, nullptr};
        return Q3Ellipsoid_New(&d);
    }
    case Kind::kTorus: {
        const TQ3TorusData d{o, z, x, y, float(s.ratio), u0, u1, v0, v1, s.caps, nullptr, nullptr};
        return Q3Torus_New(&d);
    }
    }
    return nullptr;
}

/// A decomposition read back through the public API.
struct Mesh {
    std::vector<Vec3> points;
    std::vector<Vec3> normals;
    std::vector<Real> us, vs;
    std::vector<unsigned long> triangles;
};

Mesh readMesh(TQ3GeometryObject triMesh)
{
    Mesh m;
    TQ3TriMeshData d{};
    if (Q3TriMesh_GetData(triMesh, &d) != kQ3Success)
        return m;
    for (unsigned long i = 0; i < d.numPoints; ++i)
        m.points.push_back({d.points[i].x, d.points[i].y, d.points[i].z});
    for (unsigned long a = 0; a < d.numVertexAttributeTypes; ++a) {
        const TQ3TriMeshAttributeData& attr = d.vertexAttributeTypes[a];
        EXPECT_EQ(attr.attributeUseArray, nullptr) << "every vertex has a normal and a uv";
        for (unsigned long i = 0; i < d.numPoints; ++i) {
            if (attr.attributeType == kQ3AttributeTypeNormal) {
                m.normals.push_back(fromVector(static_cast<const TQ3Vector3D*>(attr.data)[i]));
            } else if (attr.attributeType == kQ3AttributeTypeSurfaceUV) {
                const TQ3Param2D uv = static_cast<const TQ3Param2D*>(attr.data)[i];
                m.us.push_back(uv.u);
                m.vs.push_back(uv.v);
            }
        }
    }
    for (unsigned long t = 0; t < d.numTriangles; ++t)
        for (int k = 0; k < 3; ++k)
            m.triangles.push_back(d.triangles[t].pointIndices[k]);
    Q3TriMesh_EmptyData(&d);
    return m;
}

/// One random shape with everything it is drawn under.
struct Scene : SceneCamera {
    Shape shape;
    TransformStack transforms;
    bool screen = false;
    float c1 = 1;

    Scene() { pane = {{0, 0}, {float(kWidth), float(kHeight)}}; }
    /// The screen map (the `screen` member says whether the scene is drawn).
    ScreenMap map() const { return SceneCamera::screen(); }

};

/// A camera looking at the shape from a random direction; a perspective one
/// close enough that the hither plane cuts some shapes.
void aimAt(std::mt19937& rng, Scene& scene)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const Matrix4 toWorld = scene.transforms.localToWorld();
    const Vec3 centre = toWorld.point(scene.shape.origin);
    Real radius = 0;
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner = scene.shape.origin + ((i & 1) ? 1.5L : -1.5L) * scene.shape.x +
                            ((i & 2) ? 1.5L : -1.5L) * scene.shape.y + ((i & 4) ? 1.5L : -1.5L) * scene.shape.z;
        radius = std::max(radius, distance(toWorld.point(corner), centre));
    }
    const Vec3 direction = unit(randomVector(rng, 1, 1));
    Vec3 up = randomVector(rng, 1, 1);
    while (norm(cross(up, direction)) < 0.3L)
        up = randomVector(rng, 1, 1);
    scene.perspective = u(rng) < 0.5;
    if (scene.perspective) {
        const Real away = radius * Real(0.8 + 2.5 * u(rng));
        const Real fov = 0.5 + 0.8 * u(rng);
        scene.setPerspective(lookAt(centre + away * direction, centre, up, 0.05L * radius, 100 * radius), fov,
                             Real(float(kWidth) / float(kHeight)));
    } else {
        const Real half = radius * Real(0.6 + 0.8 * u(rng));
        scene.setOrthographic(lookAt(centre + 3 * radius * direction, centre, up, 0.1L * radius, 100 * radius),
                              half * 4 / 3, half);
    }
}

/// A rotation, a uniform scale and a translation: the transforms most
/// scenes use, which keep the shape's proportions.
TransformStack similarityTransforms(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    TransformStack stack;
    TransformStep rotate;
    rotate.kind = TransformStep::kRotate;
    rotate.rotate = {TQ3Axis(int(3 * u(rng)) % 3), float(6.2831853 * u(rng) - 3.14159265)};
    TransformStep scale;
    scale.kind = TransformStep::kScale;
    const float f = float(std::exp(std::log(0.25) + u(rng) * std::log(16.0)));
    scale.vector = {f, f, f};
    TransformStep translate;
    translate.kind = TransformStep::kTranslate;
    translate.vector = {float(20 * u(rng) - 10), float(20 * u(rng) - 10), float(20 * u(rng) - 10)};
    stack.steps = {translate, rotate, scale};
    return stack;
}

/// A scene; `general` transforms are SubdivisionReference.h's random stacks
/// (shear, scales of 1/4 to 4 on each axis, mirrors), else similarities.
Scene makeScene(std::mt19937& rng, Kind kind, bool screen, bool general)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    scene.shape = randomShape(rng, kind);
    scene.transforms = general ? randomTransforms(rng, int(4 * u(rng)) % 4) : similarityTransforms(rng);
    scene.screen = screen;
    if (screen) {
        aimAt(rng, scene);
        scene.c1 = float(2 + 8 * u(rng));
    } else {
        // World units: a fraction of the shape's world size.
        const Matrix4 toWorld = scene.transforms.localToWorld();
        const Real size =
            distance(toWorld.point(scene.shape.origin), toWorld.point(scene.shape.origin + scene.shape.x));
        scene.c1 = float(size * Real(0.06 + 0.14 * u(rng)));
    }
    return scene;
}

/// The shape's data, for failure messages.
std::string describe(const Scene& scene)
{
    const Shape& s = scene.shape;
    char text[512];
    std::snprintf(text, sizeof text,
                  " (origin %.9g %.9g %.9g, x %.9g %.9g %.9g, y %.9g %.9g %.9g, z %.9g %.9g %.9g, ratio %.9g, "
                  "u %.9g..%.9g, v %.9g..%.9g, caps %lu, c1 %.9g)",
                  double(s.origin.x), double(s.origin.y), double(s.origin.z), double(s.x.x), double(s.x.y),
                  double(s.x.z), double(s.y.x), double(s.y.y), double(s.y.z), double(s.z.x), double(s.z.y),
                  double(s.z.z), double(s.ratio), double(s.uMin), double(s.uMax), double(s.vMin), double(s.vMax),
                  s.caps, double(scene.c1));
    std::string result = text;
    const Matrix4 m = scene.transforms.localToWorld();
    result += " local to world (";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
            result += std::to_string(double(m.m[i][j])) + (i == 3 && j == 2 ? ")" : " ");
    return result;
}

/// What the checks found over a run, for the ratio report.
struct Totals {
    Real worstRatio = 0;
    Real ratioSum = 0;
    int ratioCount = 0;
    Real longestEdge = 0; ///< as a fraction of c1
};

class QuadricPropertyTest : public q3test::PixmapViewTest {
protected:
    QuadricPropertyTest() : PixmapViewTest(kWidth, kHeight) {}

    /// The decomposition of `geometry` under the style and the scene's
    /// transforms: in a rendering loop through the scene's camera (screen
    /// space), or in a bounding loop (world space and constant).
    Mesh decompose(const Scene& scene, TQ3GeometryObject geometry, const TQ3SubdivisionStyleData& style)
    {
        Mesh mesh;
        const bool render = scene.screen;
        if (render) {
            useCamera(scene.newObject());
            EXPECT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        } else {
            EXPECT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
        }
        TQ3ViewStatus status;
        do {
            EXPECT_EQ(Q3SubdivisionStyle_Submit(&style, m_view), kQ3Success);
            scene.transforms.submit(m_view);
            TQ3GeometryObject triMesh = Q3Geometry_GetDecomposed(geometry, m_view);
            EXPECT_NE(triMesh, nullptr);
            if (triMesh != nullptr) {
                EXPECT_EQ(Q3Geometry_GetType(triMesh), kQ3GeometryTypeTriMesh);
                mesh = readMesh(triMesh);
                Q3Object_Dispose(triMesh);
            }
            if (render) {
                status = Q3View_EndRendering(m_view);
            } else {
                TQ3BoundingBox box;
                status = Q3View_EndBoundingBox(m_view, &box);
            }
        } while (status == kQ3ViewStatusRetraverse);
        EXPECT_EQ(status, kQ3ViewStatusDone);
        return mesh;
    }

    /// Every vertex on a part, with that part's normal; the parts and range
    /// ends reached. Returns the parts seen.
    void checkOnShape(const Shape& s, const Mesh& m, const std::string& what)
    {
        ASSERT_EQ(m.normals.size(), m.points.size()) << what;
        ASSERT_EQ(m.us.size(), m.points.size()) << what;
        const Real tolerance = kOnShape * s.scale();
        std::vector<std::string> seen;
        Real uLow = 1e30L, uHigh = -1e30L, vLow = 1e30L, vHigh = -1e30L;
        int failures = 0;
        for (std::size_t i = 0; i < m.points.size(); ++i) {
            EXPECT_NEAR(double(norm(m.normals[i])), 1.0, double(kNormalSlack)) << what << " vertex " << i;
            const char* matched = nullptr;
            Real nearest = 1e30L;
            for (const Candidate& c : candidates(s, m.us[i], m.vs[i])) {
                const Real d = distance(c.point, m.points[i]);
                nearest = std::min(nearest, d);
                if (d <= tolerance && dot(c.normal, unit(m.normals[i])) >= 1 - kNormalSlack) {
                    matched = c.part;
                    break;
                }
            }
            if (matched == nullptr) {
                if (failures++ < 3)
                    ADD_FAILURE() << what << ": vertex " << i << " (" << double(m.points[i].x) << ", "
                                  << double(m.points[i].y) << ", " << double(m.points[i].z) << ") uv ("
                                  << double(m.us[i]) << ", " << double(m.vs[i])
                                  << ") is on no part of the shape with its normal (nearest "
                                  << double(nearest / s.scale()) << " of the scale)";
                continue;
            }
            if (std::find(seen.begin(), seen.end(), matched) == seen.end())
                seen.push_back(matched);
            if (std::string(matched) == "face" && s.kind != Kind::kDisk) {
                uLow = std::min(uLow, m.us[i]);
                uHigh = std::max(uHigh, m.us[i]);
                vLow = std::min(vLow, m.vs[i]);
                vHigh = std::max(vHigh, m.vs[i]);
            }
        }
        std::vector<std::string> expected = expectedParts(s);
        std::sort(expected.begin(), expected.end());
        std::sort(seen.begin(), seen.end());
        EXPECT_EQ(seen, expected) << what << ": the parts drawn are not the ones the caps ask for";
        if (s.kind != Kind::kBox && s.kind != Kind::kDisk) {
            EXPECT_NEAR(double(uLow), double(s.uMin), 1e-6) << what << ": u does not reach uMin";
            EXPECT_NEAR(double(uHigh), double(s.uEnd()), 1e-6) << what << ": u does not reach uMax";
            EXPECT_NEAR(double(vLow), double(s.vMin), 1e-6) << what << ": v does not reach vMin";
            EXPECT_NEAR(double(vHigh), double(s.vEnd()), 1e-6) << what << ": v does not reach vMax";
        }
    }

    /// Counterclockwise seen from outside: each triangle's winding normal
    /// agrees with its vertices' normals. "Outside" is only defined for a
    /// triangle whose corners' normals agree (within 60 degrees; a coarse
    /// triangle across a sharply curved part has none), and a thin triangle
    /// (height below a fifth of its longest side, as in a strongly skewed
    /// frame where rows slant) may lie either way across the surface's
    /// curvature.
    static void checkOrientation(const Shape& s, const Mesh& m, const std::string& what)
    {
        (void)s;
        int reversed = 0;
        for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
            const std::size_t i0 = m.triangles[t], i1 = m.triangles[t + 1], i2 = m.triangles[t + 2];
            const Vec3 a = m.points[i0], b = m.points[i1], c = m.points[i2];
            const Vec3 n = cross(b - a, c - a);
            const Real longest = std::max({distance(a, b), distance(b, c), distance(c, a)});
            if (norm(n) / longest <= longest / 5)
                continue;
            const Vec3 na = unit(m.normals[i0]), nb = unit(m.normals[i1]), nc = unit(m.normals[i2]);
            if (dot(na, nb) < 0.5L || dot(nb, nc) < 0.5L || dot(nc, na) < 0.5L)
                continue;
            const Vec3 sum = na + nb + nc;
            if (dot(n, sum) <= 0 && reversed++ < 3) {
                ADD_FAILURE() << what << ": triangle " << t / 3 << " faces inwards";
                for (int k = 0; k < 3; ++k) {
                    auto i = m.triangles[t + k];
                    std::printf("  v %lu p (%g %g %g) n (%g %g %g) uv (%g %g)\n", i, double(m.points[i].x),
                                double(m.points[i].y), double(m.points[i].z), double(m.normals[i].x),
                                double(m.normals[i].y), double(m.normals[i].z), double(m.us[i]), double(m.vs[i]));
                }
            }
        }
    }

    /// Every edge's drawn length at most c1; the count against the lower
    /// bound area / (sqrt(3)/4 c1^2), added to `totals` (if not null).
    void checkEdges(const Scene& scene, const Mesh& m, const std::string& what, Totals* totals, Real ratioBound = 2.6L)
    {
        const Matrix4 toWorld = scene.transforms.localToWorld();
        const ScreenMap screen = scene.map();
        const Real hither = scene.hither();
        std::vector<Vec3> world;
        for (const Vec3& p : m.points)
            world.push_back(toWorld.point(p));
        // The drawn image of a world point: world units, or pixels (false
        // nearer than the hither plane).
        auto image = [&](const Vec3& w, Vec3& out) {
            if (!scene.screen) {
                out = w;
                return true;
            }
            if (screen.depth(w) < hither)
                return false;
            Real px, py;
            if (!screen.map(w, px, py))
                return false;
            out = {px, py, 0};
            return true;
        };
        auto drawn = [&](const Vec3& a, const Vec3& b) -> Real {
            Vec3 ia, ib;
            const bool ha = image(a, ia), hb = image(b, ib);
            if (ha && hb)
                return distance(ia, ib);
            if (!ha && !hb)
                return 0;
            // The depth is affine along the world segment: cut it at hither.
            const Real da = screen.depth(a), db = screen.depth(b);
            const Vec3 cut = a + ((hither - da) / (db - da)) * (b - a);
            Vec3 ic;
            image(cut, ic);
            return distance(ha ? ia : ib, ic);
        };
        Real longest = 0, area = 0;
        std::size_t counted = 0;
        for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
            const Vec3 w[3] = {world[m.triangles[t]], world[m.triangles[t + 1]], world[m.triangles[t + 2]]};
            for (int k = 0; k < 3; ++k)
                longest = std::max(longest, drawn(w[k], w[(k + 1) % 3]));
            Vec3 i0, i1, i2;
            if (image(w[0], i0) && image(w[1], i1) && image(w[2], i2)) {
                area += norm(cross(i1 - i0, i2 - i0)) / 2;
                ++counted;
            }
        }
        EXPECT_LE(double(longest), scene.c1 * (1 + double(kEdgeSlack))) << what << ": an edge is longer than c1";
        if (totals == nullptr)
            return;
        totals->longestEdge = std::max(totals->longestEdge, longest / scene.c1);
        // The bound only means something with many triangles of the area.
        if (counted == m.triangles.size() / 3 && counted >= 300) {
            const Real ratio = counted * (std::sqrt(Real(3)) / 4 * scene.c1 * scene.c1) / area;
            if (std::getenv("Q3_QUADRIC_VERBOSE"))
                std::printf("%s: %zu triangles, ratio %.3f\n", what.c_str(), counted, double(ratio));
            EXPECT_GE(double(ratio), 1.0 - 1e-6) << what;
            if (ratioBound > 0)
                EXPECT_LE(double(ratio), ratioBound) << what << ": far more triangles than needed";
            totals->worstRatio = std::max(totals->worstRatio, ratio);
            totals->ratioSum += ratio;
            ++totals->ratioCount;
        }
    }

};

TEST_F(QuadricPropertyTest, WorldAndScreenSpaceTrianglesLieOnTheShapeAndRespectC1)
{
    std::mt19937 rng(seed());
    Totals world, screen, general;
    for (const Kind kind : kKinds)
        for (int i = 0; i < 3 * kScenesPerKind; ++i) {
            const bool onScreen = i % 3 == 1;
            const bool generalTransforms = i % 3 == 2;
            const Scene scene = makeScene(rng, kind, onScreen, generalTransforms);
            const std::string what = std::string(nameOf(kind)) + " " + std::to_string(i) +
                                     (onScreen ? (scene.perspective ? " perspective" : " orthographic") : " world") +
                                     (generalTransforms ? " (affine)" : "") + describe(scene);
            TQ3GeometryObject geometry = newGeometry(scene.shape);
            ASSERT_NE(geometry, nullptr) << what;
            const TQ3SubdivisionStyleData style = {
                onScreen ? kQ3SubdivisionMethodScreenSpace : kQ3SubdivisionMethodWorldSpace, scene.c1, scene.c1};
            const Mesh mesh = decompose(scene, geometry, style);
            Q3Object_Dispose(geometry);
            ASSERT_FALSE(mesh.triangles.empty()) << what;
            checkOnShape(scene.shape, mesh, what);
            checkOrientation(scene.shape, mesh, what);
            checkEdges(scene, mesh, what, generalTransforms ? &general : onScreen ? &screen : &world, 0);
        }
    for (const auto& [name, t] : {std::pair<const char*, const Totals&>{"world space", world},
                                  {"screen space", screen},
                                  {"world space, general affine transforms", general}})
        std::printf("[ quadrics ] %s: triangles / lower bound %.3f on average, %.3f at worst (%d shapes); "
                    "longest edge %.5f c1\n",
                    name, double(t.ratioSum / std::max(1, t.ratioCount)), double(t.worstRatio), t.ratioCount,
                    double(t.longestEdge));
}

// The count against the area bound where the bound is fair: world space, a
// similarity transform, round or mildly elliptic shapes (rows of a shape
// whose radii differ a lot, or a frame far from orthogonal, are spaced for
// their widest part, and a foreshortened view has thin triangles that no
// tessellation avoids: the test above reports those counts).
TEST_F(QuadricPropertyTest, RegularShapesGetCloseToTheFewestTriangles)
{
    std::mt19937 rng(seed() + 2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Totals totals;
    for (const Kind kind : kKinds)
        for (int i = 0; i < 4; ++i) {
            Scene scene;
            scene.shape = randomShape(rng, kind, true);
            scene.transforms = similarityTransforms(rng);
            const Matrix4 toWorld = scene.transforms.localToWorld();
            const Real size =
                distance(toWorld.point(scene.shape.origin), toWorld.point(scene.shape.origin + scene.shape.x));
            scene.c1 = float(size / Real(12 + 10 * u(rng)));
            const std::string what = std::string(nameOf(kind)) + " " + std::to_string(i) + describe(scene);
            TQ3GeometryObject geometry = newGeometry(scene.shape);
            ASSERT_NE(geometry, nullptr) << what;
            const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodWorldSpace, scene.c1, scene.c1};
            const Mesh mesh = decompose(scene, geometry, style);
            Q3Object_Dispose(geometry);
            checkEdges(scene, mesh, what, &totals, 4.0L);
        }
    std::printf("[ quadrics ] regular shapes, world space: triangles / lower bound %.3f on average, %.3f at worst "
                "(%d shapes)\n",
                double(totals.ratioSum / std::max(1, totals.ratioCount)), double(totals.worstRatio), totals.ratioCount);
    EXPECT_GE(totals.ratioCount, 20);
    EXPECT_LE(double(totals.ratioSum / std::max(1, totals.ratioCount)), 2.3);
}

TEST_F(QuadricPropertyTest, ConstantSubdivisionGivesTheDocumentedCounts)
{
    // c1 segments around, c2 along v; flat parts not divided across.
    struct Expected {
        Kind kind;
        bool partial;
        unsigned long caps;
        std::size_t triangles;
    };
    const Expected cases[] = {
        {Kind::kBox, false, 0, 12},
        {Kind::kCylinder, false, 0, 8 * 3 * 2},
        {Kind::kCylinder, false, kQ3EndCapMaskTop | kQ3EndCapMaskBottom, 8 * 3 * 2 + 2 * 8},
        {Kind::kCone, false, kQ3EndCapMaskBottom, 8 * (3 * 2 - 1) + 8},
        {Kind::kEllipsoid, false, 0, 8 * (3 * 2 - 2)},
        {Kind::kDisk, false, 0, 8 * (3 * 2 - 1)},
        {Kind::kTorus, false, 0, 8 * 3 * 2},
        // Half a turn: 4 segments around; the two faces of the cut have
        // 3 rows of one segment each, the first a fan at the apex for the
        // cone.
        {Kind::kCylinder, true, kQ3EndCapMaskInterior, 4 * 3 * 2 + 2 * 3 * 2},
        {Kind::kCone, true, kQ3EndCapMaskInterior, 4 * (3 * 2 - 1) + 2 * (3 * 2 - 1)},
    };
    for (const Expected& e : cases) {
        Scene scene;
        scene.shape.kind = e.kind;
        scene.shape.x = {1, 0, 0};
        scene.shape.y = {0, 1, 0};
        scene.shape.z = {0, 0, e.kind == Kind::kTorus ? Real(0.25) : Real(2)};
        scene.shape.ratio = 1;
        scene.shape.caps = e.caps;
        if (e.partial)
            scene.shape.uMax = 0.5L;
        TQ3GeometryObject geometry = newGeometry(scene.shape);
        ASSERT_NE(geometry, nullptr);
        const TQ3SubdivisionStyleData style = {kQ3SubdivisionMethodConstant, 8, 3};
        const Mesh mesh = decompose(scene, geometry, style);
        Q3Object_Dispose(geometry);
        EXPECT_EQ(mesh.triangles.size() / 3, e.triangles) << nameOf(e.kind) << (e.partial ? " half" : "");
        checkOnShape(scene.shape, mesh, nameOf(e.kind));
        checkOrientation(scene.shape, mesh, nameOf(e.kind));
    }
}

TEST_F(QuadricPropertyTest, AnEllipseIsANearMinimalPolylineOnTheEllipse)
{
    std::mt19937 rng(seed() + 1);
    for (int i = 0; i < 12; ++i) {
        Scene scene = makeScene(rng, Kind::kDisk, i % 2 == 1, i % 4 == 2);
        const Shape& s = scene.shape;
        const TQ3EllipseData data{toPoint(s.origin), toVector(s.x), toVector(s.y),
                                  float(s.uMin),     float(s.uMax), nullptr};
        TQ3GeometryObject ellipse = Q3Ellipse_New(&data);
        ASSERT_NE(ellipse, nullptr);
        const TQ3SubdivisionStyleData style = {
            scene.screen ? kQ3SubdivisionMethodScreenSpace : kQ3SubdivisionMethodWorldSpace, scene.c1, scene.c1};
        std::vector<Vec3> points;
        if (scene.screen) {
            useCamera(scene.newObject());
            ASSERT_EQ(Q3View_StartRendering(m_view), kQ3Success);
        } else {
            ASSERT_EQ(Q3View_StartBoundingBox(m_view, kQ3ComputeBoundsExact), kQ3Success);
        }
        Q3SubdivisionStyle_Submit(&style, m_view);
        scene.transforms.submit(m_view);
        TQ3GeometryObject polyLine = Q3Geometry_GetDecomposed(ellipse, m_view);
        ASSERT_NE(polyLine, nullptr);
        EXPECT_EQ(Q3Geometry_GetType(polyLine), kQ3GeometryTypePolyLine);
        TQ3PolyLineData line{};
        ASSERT_EQ(Q3PolyLine_GetData(polyLine, &line), kQ3Success);
        for (unsigned long v = 0; v < line.numVertices; ++v)
            points.push_back(toVec(line.vertices[v].point));
        Q3PolyLine_EmptyData(&line);
        Q3Object_Dispose(polyLine);
        if (scene.screen) {
            EXPECT_EQ(Q3View_EndRendering(m_view), kQ3ViewStatusDone);
        } else {
            TQ3BoundingBox box;
            EXPECT_EQ(Q3View_EndBoundingBox(m_view, &box), kQ3ViewStatusDone);
        }
        Q3Object_Dispose(ellipse);

        // On the ellipse: in the frame (x, y, x ^ y) the point is (cos, sin, 0)
        // at an angle within the range; the ends exactly uMin and uMax.
        const Vec3 n = cross(s.x, s.y);
        auto turnsOf = [&](const Vec3& p, Real& radius, Real& off) {
            const Vec3 d = p - s.origin;
            const Real det = dot(s.x, cross(s.y, n));
            const Real a = dot(d, cross(s.y, n)) / det, b = dot(d, cross(n, s.x)) / det;
            off = dot(d, cross(s.x, s.y)) / det;
            radius = std::hypot(a, b);
            return std::atan2(b, a) / (2 * kPi);
        };
        ASSERT_GE(points.size(), 2u);
        for (std::size_t k = 0; k < points.size(); ++k) {
            Real radius, off;
            const Real turns = turnsOf(points[k], radius, off);
            EXPECT_NEAR(double(radius), 1.0, double(kOnShape * s.scale())) << "ellipse " << i << " vertex " << k;
            EXPECT_NEAR(double(off), 0.0, double(kOnShape * s.scale())) << "ellipse " << i;
            EXPECT_TRUE(angleWithin(s, turns)) << "ellipse " << i << " vertex " << k << " outside the range";
        }
        Real r, off;
        const Real first = turnsOf(points.front(), r, off), last = turnsOf(points.back(), r, off);
        auto sameAngle = [](Real a, Real b) { return std::fabs(std::remainder(double(a - b), 1.0)) < 1e-6; };
        EXPECT_TRUE(sameAngle(first, s.uMin)) << "ellipse " << i << " does not start at uMin";
        EXPECT_TRUE(sameAngle(last, s.uMax)) << "ellipse " << i << " does not end at uMax";

        // Segments of drawn length in [0.98, 1] c1 but the last.
        Mesh asMesh;
        asMesh.points = points;
        for (std::size_t k = 0; k + 1 < points.size(); ++k)
            asMesh.triangles.insert(asMesh.triangles.end(), {k, k + 1, k + 1});
        checkEdges(scene, asMesh, "ellipse " + std::to_string(i), nullptr);
        if (!scene.screen || !scene.perspective) {
            const Matrix4 toWorld = scene.transforms.localToWorld();
            const ScreenMap screen = scene.map();
            for (std::size_t k = 0; k + 2 < points.size(); ++k) {
                const Vec3 a = toWorld.point(points[k]), b = toWorld.point(points[k + 1]);
                Real length = distance(a, b);
                if (scene.screen) {
                    Real ax, ay, bx, by;
                    screen.map(a, ax, ay);
                    screen.map(b, bx, by);
                    length = std::hypot(bx - ax, by - ay);
                }
                EXPECT_GE(double(length), 0.98 * scene.c1 * (1 - 1e-4)) << "ellipse " << i << " segment " << k;
            }
        }
    }
}

} // namespace
