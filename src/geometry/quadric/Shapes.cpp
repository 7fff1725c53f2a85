// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The patches of each shape (Shapes.h states the parameterisations). The
// affine shapes evaluate their canonical form and map it through the frame;
// the torus evaluates its own formula and the cross product of its partial
// derivatives:
//   dP/dtheta = a' - cos(psi) k ahat',  ahat' = (a' - (ahat . a') ahat) / |a|
//   dP/dpsi   = -cos(psi) z + sin(psi) k ahat
// (a' = -sin theta x + cos theta y), oriented once per patch by a point whose
// outward direction is known.

#include "geometry/quadric/Shapes.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace q3::quadric {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kPi = 3.141592653589793238462643383280;

Vec3 unit(const Vec3& v)
{
    const double length = glm::length(v);
    return length > 0.0 ? v / length : Vec3(0.0);
}

ConstantRule aroundRule(const Range& u)
{
    return ConstantRule{1, u.length(), u.full() ? 3u : 1u};
}

// ---- The affine shapes -------------------------------------------------------

/// The profile of a revolved side: its canonical radius and height at v.
enum class Profile { kCylinder, kCone, kEllipsoid };

double profileRadius(Profile profile, double v)
{
    switch (profile) {
    case Profile::kCylinder:
        return 1.0;
    case Profile::kCone:
        return 1.0 - v;
    case Profile::kEllipsoid:
        return std::sin(kPi * v);
    }
    return 1.0;
}

double profileHeight(Profile profile, double v)
{
    return profile == Profile::kEllipsoid ? -std::cos(kPi * v) : v;
}

/// The side of a cone, a cylinder or an ellipsoid.
class Side final : public Patch {
public:
    Side(const Frame& frame, Profile profile) : m_frame(frame), m_profile(profile) {}

    Vec3 point(double u, double v) const override
    {
        const double r = profileRadius(m_profile, v), theta = kTwoPi * u;
        return m_frame.point(Vec3(r * std::cos(theta), r * std::sin(theta), profileHeight(m_profile, v)));
    }
    Vec3 normal(double u, double v) const override
    {
        const double theta = kTwoPi * u, c = std::cos(theta), s = std::sin(theta);
        switch (m_profile) {
        case Profile::kCylinder:
            return m_frame.normal(Vec3(c, s, 0.0));
        case Profile::kCone:
            return m_frame.normal(Vec3(c, s, 1.0));
        case Profile::kEllipsoid:
            break;
        }
        const double phi = kPi * v;
        return m_frame.normal(Vec3(std::sin(phi) * c, std::sin(phi) * s, -std::cos(phi)));
    }
    Vec2 uv(double u, double v) const override { return Vec2(u, v); }

private:
    Frame m_frame;
    Profile m_profile;
};

/// A flat elliptic disk (or a part of one) in the frame's plane z = height,
/// radius `radius` times the frame's x and y, facing +z or -z: the disk
/// geometry, and caps. u in turns, v the radial fraction.
class FlatDisk final : public Patch {
public:
    FlatDisk(const Frame& frame, double height, double radius, double facing)
        : m_frame(frame), m_height(height), m_radius(radius), m_facing(facing)
    {
    }

    Vec3 point(double u, double v) const override
    {
        const double theta = kTwoPi * u, r = m_radius * v;
        return m_frame.point(Vec3(r * std::cos(theta), r * std::sin(theta), m_height));
    }
    Vec3 normal(double, double) const override { return m_frame.normal(Vec3(0.0, 0.0, m_facing)); }
    Vec2 uv(double u, double v) const override
    {
        const double theta = kTwoPi * u;
        return Vec2(0.5 + 0.5 * v * std::cos(theta), 0.5 + 0.5 * v * std::sin(theta));
    }

private:
    Frame m_frame;
    double m_height, m_radius, m_facing;
};

/// The face of a cut at angle `turn` (uMin or uMax): from the axis (u = 0)
/// to the side's profile (u = 1), along the side's v.
class CutFace final : public Patch {
public:
    CutFace(const Frame& frame, Profile profile, double turn, bool atMin)
        : m_frame(frame), m_profile(profile), m_cos(std::cos(kTwoPi * turn)), m_sin(std::sin(kTwoPi * turn)),
          m_atMin(atMin)
    {
    }

    Vec3 point(double s, double v) const override
    {
        const double r = s * profileRadius(m_profile, v);
        return m_frame.point(Vec3(r * m_cos, r * m_sin, profileHeight(m_profile, v)));
    }
    Vec3 normal(double, double) const override
    {
        // The solid lies counterclockwise from uMin and clockwise from uMax.
        const Vec3 towardsIncreasingU(-m_sin, m_cos, 0.0);
        return m_frame.normal(m_atMin ? -towardsIncreasingU : towardsIncreasingU);
    }
    Vec2 uv(double s, double v) const override { return Vec2(s, v); }

private:
    Frame m_frame;
    Profile m_profile;
    double m_cos, m_sin;
    bool m_atMin;
};

/// A face of the unit cube: canonical point corner + u du + v dv, outward
/// normal n.
class BoxFace final : public Patch {
public:
    BoxFace(const Frame& frame, const Vec3& corner, const Vec3& du, const Vec3& dv, const Vec3& n)
        : m_frame(frame), m_corner(corner), m_du(du), m_dv(dv), m_normal(frame.normal(n))
    {
    }

    Vec3 point(double u, double v) const override { return m_frame.point(m_corner + u * m_du + v * m_dv); }
    Vec3 normal(double, double) const override { return m_normal; }
    Vec2 uv(double u, double v) const override { return Vec2(u, v); }

private:
    Frame m_frame;
    Vec3 m_corner, m_du, m_dv, m_normal;
};

// ---- The torus -----------------------------------------------------------------

struct TorusFrame {
    Vec3 origin, x, y, z;
    double k = 0.0; ///< ratio * |z|

    Vec3 ring(double theta) const { return std::cos(theta) * x + std::sin(theta) * y; }
    Vec3 ringTangent(double theta) const { return -std::sin(theta) * x + std::cos(theta) * y; }
    /// From the ring's point at theta to the surface at psi.
    Vec3 spoke(double theta, double psi) const { return -std::sin(psi) * z - std::cos(psi) * k * unit(ring(theta)); }
    Vec3 centre(double theta) const { return origin + ring(theta); }
    Vec3 dTheta(double theta, double psi, double s) const
    {
        const Vec3 a = ring(theta), da = ringTangent(theta);
        const double length = glm::length(a);
        const Vec3 ahat = a / length;
        const Vec3 dahat = (da - glm::dot(ahat, da) * ahat) / length;
        return da - s * std::cos(psi) * k * dahat;
    }
    Vec3 dPsi(double theta, double psi) const { return -std::cos(psi) * z + std::sin(psi) * k * unit(ring(theta)); }
};

/// The torus surface (u = theta / 2 pi, v = psi / 2 pi).
class TorusSkin final : public Patch {
public:
    explicit TorusSkin(const TorusFrame& frame) : m_frame(frame) {}

    /// Call once the domain is set. At the outer equator (psi = pi) the
    /// outside is along the ring's radius.
    void orient()
    {
        const double theta = kPi * (u0 + u1);
        m_sign = glm::dot(raw(theta, kPi), m_frame.ring(theta)) < 0.0 ? -1.0 : 1.0;
    }

    Vec3 point(double u, double v) const override
    {
        const double theta = kTwoPi * u, psi = kTwoPi * v;
        return m_frame.centre(theta) + m_frame.spoke(theta, psi);
    }
    Vec3 normal(double u, double v) const override { return m_sign * unit(raw(kTwoPi * u, kTwoPi * v)); }
    Vec2 uv(double u, double v) const override { return Vec2(u, v); }

private:
    Vec3 raw(double theta, double psi) const
    {
        return glm::cross(m_frame.dTheta(theta, psi, 1.0), m_frame.dPsi(theta, psi));
    }

    TorusFrame m_frame;
    double m_sign = 1.0;
};

/// A cross-section of the tube at angle `turn`: u along the tube's v (turns),
/// v the fraction from the tube's centre (0) to its surface (1).
class TorusSection final : public Patch {
public:
    TorusSection(const TorusFrame& frame, double turn, bool atMin) : m_frame(frame), m_theta(kTwoPi * turn)
    {
        const Vec3 n = unit(glm::cross(m_frame.z, m_frame.ring(m_theta)));
        // Outward is against the ring's direction at uMin, along it at uMax.
        const double along = glm::dot(n, m_frame.ringTangent(m_theta));
        m_normal = (along < 0.0) == atMin ? n : -n;
    }

    Vec3 point(double u, double v) const override
    {
        return m_frame.centre(m_theta) + v * m_frame.spoke(m_theta, kTwoPi * u);
    }
    Vec3 normal(double, double) const override { return m_normal; }
    Vec2 uv(double u, double v) const override
    {
        const double psi = kTwoPi * u;
        return Vec2(0.5 + 0.5 * v * std::cos(psi), 0.5 + 0.5 * v * std::sin(psi));
    }

private:
    TorusFrame m_frame;
    double m_theta;
    Vec3 m_normal;
};

/// The wall from the tube's centre line (v = 0) to the cut edge at the tube
/// angle `turn` (v = 1), along the ring (u in turns).
class TorusWall final : public Patch {
public:
    TorusWall(const TorusFrame& frame, double turn, bool atMin) : m_frame(frame), m_psi(kTwoPi * turn), m_atMin(atMin)
    {
    }

    /// Call once the domain is set: outward is against increasing v at vMin,
    /// along it at vMax.
    void orient()
    {
        const double theta = kPi * (u0 + u1);
        const double along = glm::dot(raw(theta, 0.5), m_frame.dPsi(theta, m_psi));
        m_sign = (along < 0.0) == m_atMin ? 1.0 : -1.0;
    }

    Vec3 point(double u, double v) const override
    {
        const double theta = kTwoPi * u;
        return m_frame.centre(theta) + v * m_frame.spoke(theta, m_psi);
    }
    Vec3 normal(double u, double v) const override { return m_sign * unit(raw(kTwoPi * u, v)); }
    Vec2 uv(double u, double v) const override { return Vec2(u, v); }

private:
    Vec3 raw(double theta, double s) const
    {
        return glm::cross(m_frame.dTheta(theta, m_psi, s), m_frame.spoke(theta, m_psi));
    }

    TorusFrame m_frame;
    double m_psi;
    bool m_atMin;
    double m_sign = 1.0;
};

template <class P> P& add(Patches& patches, std::unique_ptr<P> patch)
{
    P& ref = *patch;
    patches.push_back(std::move(patch));
    return ref;
}

void setDomain(Patch& p, const Range& u, const Range& v)
{
    p.u0 = u.min;
    p.u1 = u.max;
    p.v0 = v.min;
    p.v1 = v.max;
}

/// The side and the caps and cut faces common to cones, cylinders and
/// ellipsoids.
Patches revolvedPatches(const RevolvedShape& shape, Profile profile)
{
    const Frame frame(shape.origin, shape.majorRadius, shape.minorRadius, shape.orientation);
    const Range radial{0.0, 1.0};
    const bool fullU = shape.u.full();
    const ConstantRule around = aroundRule(shape.u);
    // The poles and the apex, where a row is one point.
    const bool pointAtV0 = profile == Profile::kEllipsoid && shape.v.min == 0.0;
    const bool pointAtV1 = profile != Profile::kCylinder && shape.v.max == 1.0;
    Patches patches;

    Patch& side = add(patches, std::make_unique<Side>(frame, profile));
    setDomain(side, shape.u, shape.v);
    side.collapsedV0 = pointAtV0;
    side.collapsedV1 = pointAtV1;
    side.closedU = fullU;
    side.turnsU = shape.u.length();
    side.turnsV = profile == Profile::kEllipsoid ? 0.5 * shape.v.length() : 0.0;
    side.constantU = around;
    side.constantV = ConstantRule{2, shape.v.length(), side.collapsedV0 && side.collapsedV1 ? 2u : 1u};

    // A cap: the disk closing the side's row at v (its first or last row).
    auto cap = [&](double v, double facing, int part, bool lastRowOfSide) {
        if (lastRowOfSide ? pointAtV1 : pointAtV0)
            return;
        Patch& disk = add(
            patches, std::make_unique<FlatDisk>(frame, profileHeight(profile, v), profileRadius(profile, v), facing));
        setDomain(disk, shape.u, radial);
        disk.collapsedV0 = true;
        disk.closedU = fullU;
        disk.turnsU = shape.u.length();
        disk.constantU = around;
        disk.part = part;
        disk.link.last = RowSource{0, lastRowOfSide ? RowSource::kLastRow : RowSource::kFirstRow};
    };
    const bool ellipsoid = profile == Profile::kEllipsoid;
    if (shape.caps & kCapBottom)
        cap(shape.v.min, -1.0, ellipsoid ? kPartInterior : kPartBottom, false);
    if (profile == Profile::kCone) {
        if ((shape.caps & kCapInterior) && shape.v.max < 1.0)
            cap(shape.v.max, 1.0, kPartInterior, true);
    } else if (shape.caps & kCapTop) {
        cap(shape.v.max, 1.0, ellipsoid ? kPartInterior : kPartTop, true);
    }
    if ((shape.caps & kCapInterior) && !fullU) {
        for (const bool atMin : {true, false}) {
            Patch& face =
                add(patches, std::make_unique<CutFace>(frame, profile, atMin ? shape.u.min : shape.u.max, atMin));
            setDomain(face, radial, shape.v);
            face.collapsedV0 = side.collapsedV0;
            face.collapsedV1 = side.collapsedV1;
            face.turnsV = side.turnsV;
            face.constantV = side.constantV;
            face.part = kPartInterior;
            face.link.rows = 0;
        }
    }
    return patches;
}

} // namespace

Range angularRange(double min, double max)
{
    return Range{min, max > min ? max : max + 1.0};
}

Frame::Frame(const Vec3& o, const Vec3& x, const Vec3& y, const Vec3& z)
    : origin(o), axes(x, y, z), normals(glm::transpose(glm::inverse(glm::dmat3(x, y, z))))
{
}

Vec3 Frame::normal(const Vec3& canonical) const
{
    return unit(normals * canonical);
}

double independence(const Vec3& x, const Vec3& y, const Vec3& z)
{
    const double scale = glm::length(x) * glm::length(y) * glm::length(z);
    return scale > 0.0 ? std::fabs(glm::dot(x, glm::cross(y, z))) / scale : 0.0;
}

double independence(const Vec3& x, const Vec3& y)
{
    const double scale = glm::length(x) * glm::length(y);
    return scale > 0.0 ? glm::length(glm::cross(x, y)) / scale : 0.0;
}

Patches boxPatches(const BoxShape& box)
{
    const Frame frame(box.origin, box.majorAxis, box.minorAxis, box.orientation);
    // corner, u direction, v direction, outward normal, in the unit cube
    // (x major, y minor, z orientation), as QuickDraw 3D orders the faces.
    struct Face {
        Vec3 corner, du, dv, n;
    };
    const Face faces[6] = {
        {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // left
        {{1, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   // right
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}},    // front
        {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {-1, 0, 0}},  // back
        {{1, 0, 1}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}},   // top
        {{1, 1, 0}, {0, -1, 0}, {-1, 0, 0}, {0, 0, -1}}, // bottom
    };
    Patches patches;
    for (int i = 0; i < 6; ++i) {
        Patch& face =
            add(patches, std::make_unique<BoxFace>(frame, faces[i].corner, faces[i].du, faces[i].dv, faces[i].n));
        face.part = i;
    }
    return patches;
}

Patches conePatches(const RevolvedShape& cone)
{
    return revolvedPatches(cone, Profile::kCone);
}

Patches cylinderPatches(const RevolvedShape& cylinder)
{
    return revolvedPatches(cylinder, Profile::kCylinder);
}

Patches ellipsoidPatches(const RevolvedShape& ellipsoid)
{
    return revolvedPatches(ellipsoid, Profile::kEllipsoid);
}

Patches diskPatches(const DiskShape& disk)
{
    const Vec3 n = unit(glm::cross(disk.majorRadius, disk.minorRadius));
    const Frame frame(disk.origin, disk.majorRadius, disk.minorRadius, n);
    Patches patches;
    Patch& face = add(patches, std::make_unique<FlatDisk>(frame, 0.0, 1.0, 1.0));
    setDomain(face, disk.u, disk.v);
    face.collapsedV0 = disk.v.min == 0.0;
    face.closedU = disk.u.full();
    face.turnsU = disk.u.length();
    face.constantU = aroundRule(disk.u);
    face.constantV = ConstantRule{2, disk.v.length(), 1};
    return patches;
}

Patches torusPatches(const TorusShape& torus)
{
    TorusFrame frame;
    frame.origin = torus.origin;
    frame.x = torus.majorRadius;
    frame.y = torus.minorRadius;
    frame.z = torus.orientation;
    frame.k = torus.ratio * glm::length(torus.orientation);
    const Range radial{0.0, 1.0};
    const bool fullU = torus.u.full(), fullV = torus.v.full();
    Patches patches;

    auto& skin = add(patches, std::make_unique<TorusSkin>(frame));
    setDomain(skin, torus.u, torus.v);
    skin.orient();
    skin.closedU = fullU;
    skin.closedV = fullV;
    skin.turnsU = torus.u.length();
    skin.turnsV = torus.v.length();
    skin.constantU = aroundRule(torus.u);
    skin.constantV = ConstantRule{2, torus.v.length(), fullV ? 3u : 1u};
    if (!(torus.caps & kCapInterior))
        return patches;

    if (!fullU) {
        for (const bool atMin : {true, false}) {
            Patch& section =
                add(patches, std::make_unique<TorusSection>(frame, atMin ? torus.u.min : torus.u.max, atMin));
            setDomain(section, torus.v, radial);
            section.collapsedV0 = true;
            section.closedU = fullV;
            section.turnsU = skin.turnsV;
            section.constantU = skin.constantV;
            section.part = kPartInterior;
            section.link.last = RowSource{0, RowSource::kRowValues};
        }
    }
    if (!fullV) {
        int firstWall = -1;
        for (const bool atMin : {true, false}) {
            auto& wall = add(patches, std::make_unique<TorusWall>(frame, atMin ? torus.v.min : torus.v.max, atMin));
            setDomain(wall, torus.u, radial);
            wall.orient();
            wall.closedU = fullU;
            wall.turnsU = skin.turnsU;
            wall.constantU = skin.constantU;
            wall.part = kPartInterior;
            // The two walls share the tube's centre line.
            if (firstWall >= 0)
                wall.link.first = RowSource{firstWall, RowSource::kFirstRow};
            firstWall = int(patches.size()) - 1;
            wall.link.last = RowSource{0, atMin ? RowSource::kFirstRow : RowSource::kLastRow};
        }
    }
    return patches;
}

Vec3 ellipsePoint(const EllipseShape& ellipse, double u)
{
    const double theta = kTwoPi * u;
    return ellipse.origin + std::cos(theta) * ellipse.majorRadius + std::sin(theta) * ellipse.minorRadius;
}

} // namespace q3::quadric
