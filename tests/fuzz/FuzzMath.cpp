// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The API fuzzer's operations on QD3DMath.h.

#include "FuzzSession.h"

namespace q3fuzz {

void Session::math()
{
    TQ3Matrix4x4 a = readMatrix();
    const TQ3Matrix4x4 b = readMatrix();
    TQ3Vector3D v1 = vector3();
    const TQ3Vector3D v2 = vector3();
    TQ3Point3D p = point3();
    const bool nullArg = m_in.u8() == 0;
    TQ3Matrix4x4 r{};
    switch (m_in.u8() % 15) {
    case 0: POINTER(Q3Matrix4x4_Invert(&a, nullArg ? nullptr : &r)); break;
    case 1: POINTER(Q3Matrix4x4_Invert(&a, &a)); break;
    case 2: POINTER(Q3Matrix4x4_Multiply(&a, nullArg ? nullptr : &b, &a)); break;
    case 3: POINTER(Q3Matrix4x4_Transpose(&a, &a)); break;
    case 4: POINTER(Q3Point3D_Transform(&p, nullArg ? nullptr : &a, &p)); break;
    case 5: POINTER(Q3Vector3D_Normalize(&v1, nullArg ? nullptr : &v1)); break;
    case 6: POINTER(Q3Vector3D_Cross(&v1, &v2, &v1)); break;
    case 7: QUERY(Q3Vector3D_Dot(&v1, nullArg ? nullptr : &v2), 0.0f); break;
    case 9: mathPoints(nullArg); break;
    case 10: mathVectors(a, nullArg); break;
    case 11: mathMatrices(a, b, v1, v2, p, nullArg); break;
    case 12: mathQuaternions(a, v1, v2, p, nullArg); break;
    case 13: mathBounds(nullArg); break;
    case 14: mathArrays(a, nullArg); break;
    default: QUERY(Q3Point3D_Distance(&p, nullArg ? nullptr : &p), 0.0f); break;
    }
}

TQ3Vector2D Session::vector2()
{
return TQ3Vector2D{m_in.value(), m_in.value()};
}

TQ3RationalPoint4D Session::point4()
{
return TQ3RationalPoint4D{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
}

TQ3Quaternion Session::quaternion()
{
return TQ3Quaternion{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
}

TQ3Matrix3x3 Session::readMatrix3x3()
{
    TQ3Matrix3x3 m{};
    const std::uint8_t mode = m_in.u8();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m.value[i][j] = (mode & 1) ? m_in.value() : (i == j ? 1.0f : 0.0f);
    if (!(mode & 1))
        for (int n = mode >> 5; n > 0; --n)
            m.value[m_in.u8() % 3][m_in.u8() % 3] = m_in.value();
    return m;
}

void Session::mathPoints(bool nullArg)
{
    TQ3Point2D p2 = point2();
    const TQ3Point2D q2 = point2();
    TQ3Param2D u{m_in.value(), m_in.value()};
    TQ3Point3D p3 = point3();
    const TQ3Point3D q3 = point3();
    TQ3RationalPoint3D r3{m_in.value(), m_in.value(), m_in.value()};
    TQ3RationalPoint4D r4 = point4();
    const TQ3RationalPoint4D s4 = point4();
    const TQ3Vector2D v2 = vector2();
    const TQ3Vector3D v3 = vector3();
    const float r1 = m_in.value(), rr2 = m_in.value();
    TQ3PolarPoint polar{m_in.value(), m_in.value()};
    TQ3SphericalPoint sphere{m_in.value(), m_in.value(), m_in.value()};
    const TQ3Matrix3x3 m = readMatrix3x3();
    TQ3Vector2D ov2{};
    TQ3Vector3D ov3{};
    switch (m_in.u8() % 24) {
    case 0: MATH_INTO(&p2, Q3Point2D_Set(nullArg ? nullptr : &p2, r1, rr2)); break;
    case 1: MATH_INTO(&r3, Q3RationalPoint3D_Set(&r3, r1, rr2, q2.x)); break;
    case 2: MATH_INTO(&sphere, Q3SphericalPoint_Set(&sphere, r1, rr2, q2.y)); break;
    case 3: MATH_INTO(&p3, Q3Point2D_To3D(nullArg ? nullptr : &p2, &p3)); break;
    case 4: MATH_INTO(&p2, Q3RationalPoint3D_To2D(&r3, &p2)); break;
    case 5: MATH_INTO(&p3, Q3RationalPoint4D_To3D(&r4, &p3)); break;
    case 6: MATH_INTO(&ov2, Q3Param2D_Subtract(&u, nullArg ? nullptr : &u, &ov2)); break;
    case 7: MATH_INTO(&ov3, Q3Point3D_Subtract(&p3, &q3, &ov3)); break;
    case 8: QUERY(Q3RationalPoint3D_Distance(&r3, nullArg ? nullptr : &r3), 0.0f); break;
    case 9: QUERY(Q3RationalPoint4D_DistanceSquared(&r4, &s4), 0.0f); break;
    case 10: QUERY(Q3Point2D_Distance(&p2, &q2), 0.0f); break;
    case 11: MATH_INTO(&p2, Q3Point2D_RRatio(&p2, &q2, r1, rr2, &p2)); break;
    case 12: MATH_INTO(&r4, Q3RationalPoint4D_RRatio(&s4, &r4, r1, rr2, nullArg ? nullptr : &r4)); break;
    case 13: MATH_INTO(&u, Q3Param2D_RRatio(&u, &u, r1, rr2, &u)); break;
    case 14: MATH_INTO(&p3, Q3Point3D_Vector3D_Add(&p3, nullArg ? nullptr : &v3, &p3)); break;
    case 15: MATH_INTO(&u, Q3Param2D_Vector2D_Subtract(&u, &v2, &u)); break;
    case 16: MATH_INTO(&ov3, Q3Point3D_CrossProductTri(&p3, &q3, &p3, &ov3)); break;
    case 17: MATH_INTO(&p2, Q3Point2D_Transform(&p2, nullArg ? nullptr : &m, &p2)); break;
    case 18: MATH_INTO(&u, Q3Param2D_Transform(&u, &m, &u)); break;
    case 19: MATH_INTO(&polar, Q3Point2D_ToPolar(&p2, &polar)); break;
    case 20: MATH_INTO(&p2, Q3PolarPoint_ToPoint2D(&polar, nullArg ? nullptr : &p2)); break;
    case 21: MATH_INTO(&sphere, Q3Point3D_ToSpherical(&p3, &sphere)); break;
    case 22: MATH_INTO(&p3, Q3SphericalPoint_ToPoint3D(&sphere, &p3)); break;
    default: MATH_INTO(&r4, Q3Point3D_To4D(&p3, &r4)); break;
    }
}

void Session::mathVectors(const TQ3Matrix4x4& m4, bool nullArg)
{
    TQ3Vector2D a = vector2();
    const TQ3Vector2D b = vector2();
    TQ3Vector3D c = vector3();
    const TQ3Vector3D d = vector3();
    const float scalar = m_in.value();
    const TQ3Matrix3x3 m3 = readMatrix3x3();
    switch (m_in.u8() % 14) {
    case 0: MATH_INTO(&a, Q3Vector2D_Set(&a, scalar, b.y)); break;
    case 1: MATH_INTO(&c, Q3Vector2D_To3D(nullArg ? nullptr : &a, &c)); break;
    case 2: MATH_INTO(&a, Q3Vector3D_To2D(&c, &a)); break;
    case 3: MATH_INTO(&a, Q3Vector2D_Scale(&a, scalar, nullArg ? nullptr : &a)); break;
    case 4: MATH_INTO(&c, Q3Vector3D_Scale(&c, scalar, &c)); break;
    case 5: QUERY(Q3Vector2D_Length(nullArg ? nullptr : &a), 0.0f); break;
    case 6: MATH_INTO(&a, Q3Vector2D_Normalize(&a, &a)); break;
    case 7: MATH_INTO(&a, Q3Vector2D_Add(&a, nullArg ? nullptr : &b, &a)); break;
    case 8: MATH_INTO(&c, Q3Vector3D_Subtract(&d, &c, &c)); break;
    case 9: QUERY(Q3Vector2D_Cross(&a, nullArg ? nullptr : &b), 0.0f); break;
    case 10: QUERY(Q3Vector2D_Dot(&a, &b), 0.0f); break;
    case 11: MATH_INTO(&a, Q3Vector2D_Transform(&a, nullArg ? nullptr : &m3, &a)); break;
    case 12: MATH_INTO(&c, Q3Vector3D_Transform(&c, &m4, &c)); break;
    default: MATH_INTO(&c, Q3Vector3D_Negate(nullArg ? nullptr : &d, &c)); break;
    }
}

void Session::mathMatrices(TQ3Matrix4x4& a, const TQ3Matrix4x4& b, const TQ3Vector3D& v1, const TQ3Vector3D& v2,
                  const TQ3Point3D& p, bool nullArg)
{
    TQ3Matrix3x3 m = readMatrix3x3();
    const TQ3Matrix3x3 n = readMatrix3x3();
    const TQ3Point2D origin = point2();
    const TQ3Quaternion q = quaternion();
    const float x = m_in.value(), y = m_in.value(), z = m_in.value();
    switch (m_in.u8() % 16) {
    case 0: MATH_INTO(&m, Q3Matrix3x3_Copy(&n, nullArg ? nullptr : &m)); break;
    case 1: MATH_INTO(&m, Q3Matrix3x3_SetIdentity(&m)); break;
    case 2: MATH_INTO(&m, Q3Matrix3x3_Transpose(&m, &m)); break;
    case 3: MATH_INTO(&m, Q3Matrix3x3_Invert(&m, nullArg ? nullptr : &m)); break;
    case 4: MATH_INTO(&m, Q3Matrix3x3_Adjoint(&m, &m)); break;
    case 5: MATH_INTO(&m, Q3Matrix3x3_Multiply(&m, nullArg ? nullptr : &n, &m)); break;
    case 6: MATH_INTO(&m, Q3Matrix3x3_SetTranslate(&m, x, y)); break;
    case 7: MATH_INTO(&m, Q3Matrix3x3_SetScale(nullArg ? nullptr : &m, x, y)); break;
    case 8: MATH_INTO(&m, Q3Matrix3x3_SetRotateAboutPoint(&m, nullArg ? nullptr : &origin, x)); break;
    case 9: MATH_INTO(&a, Q3Matrix4x4_SetRotateAboutPoint(&a, nullArg ? nullptr : &p, x, y, z)); break;
    case 10: MATH_INTO(&a, Q3Matrix4x4_SetRotate_XYZ(&a, x, y, z)); break;
    case 11: MATH_INTO(&a, Q3Matrix4x4_SetRotateVectorToVector(&a, &v1, nullArg ? nullptr : &v2)); break;
    case 12: MATH_INTO(&a, Q3Matrix4x4_SetQuaternion(&a, nullArg ? nullptr : &q)); break;
    case 13: QUERY(Q3Matrix3x3_Determinant(nullArg ? nullptr : &m), 0.0f); break;
    case 14: QUERY(Q3Matrix4x4_Determinant(&b), 0.0f); break;
    default: MATH_INTO(&a, Q3Matrix4x4_Copy(&b, &a)); break;
    }
}

void Session::mathQuaternions(const TQ3Matrix4x4& m, const TQ3Vector3D& v1, const TQ3Vector3D& v2, TQ3Point3D& p,
                     bool nullArg)
{
    TQ3Quaternion q1 = quaternion();
    const TQ3Quaternion q2 = quaternion();
    TQ3Vector3D v = v1;
    const float t = m_in.value(), x = m_in.value(), y = m_in.value(), z = m_in.value();
    switch (m_in.u8() % 20) {
    case 0: MATH_INTO(&q1, Q3Quaternion_Set(&q1, t, x, y, z)); break;
    case 1: MATH_INTO(&q1, Q3Quaternion_SetIdentity(nullArg ? nullptr : &q1)); break;
    case 2: MATH_INTO(&q1, Q3Quaternion_Copy(&q2, &q1)); break;
    case 3: QUERY(Q3Quaternion_IsIdentity(nullArg ? nullptr : &q1), kQ3False); break;
    case 4: MATH_INTO(&q1, Q3Quaternion_Invert(&q1, &q1)); break;
    case 5: MATH_INTO(&q1, Q3Quaternion_Normalize(&q1, nullArg ? nullptr : &q1)); break;
    case 6: QUERY(Q3Quaternion_Dot(&q1, nullArg ? nullptr : &q2), 0.0f); break;
    case 7: MATH_INTO(&q1, Q3Quaternion_Multiply(&q1, &q2, &q1)); break;
    case 8: MATH_INTO(&q1, Q3Quaternion_SetRotateAboutAxis(&q1, nullArg ? nullptr : &v2, t)); break;
    case 9: MATH_INTO(&q1, Q3Quaternion_SetRotate_XYZ(&q1, x, y, z)); break;
    case 10: MATH_INTO(&q1, Q3Quaternion_SetRotate_X(&q1, t)); break;
    case 11: MATH_INTO(&q1, Q3Quaternion_SetRotate_Z(&q1, t)); break;
    case 12: MATH_INTO(&q1, Q3Quaternion_SetMatrix(&q1, nullArg ? nullptr : &m)); break;
    case 13: MATH_INTO(&q1, Q3Quaternion_SetRotateVectorToVector(&q1, &v1, &v2)); break;
    case 14: MATH_INTO(&q1, Q3Quaternion_MatchReflection(&q1, &q2, &q1)); break;
    case 15: MATH_INTO(&q1, Q3Quaternion_InterpolateFast(&q1, &q2, t, nullArg ? nullptr : &q1)); break;
    case 16: MATH_INTO(&q1, Q3Quaternion_InterpolateLinear(&q2, &q1, t, &q1)); break;
    case 17: MATH_INTO(&v, Q3Vector3D_TransformQuaternion(&v, nullArg ? nullptr : &q1, &v)); break;
    case 18: MATH_INTO(&p, Q3Point3D_TransformQuaternion(&p, &q2, &p)); break;
    default: MATH_INTO(&q1, Q3Quaternion_SetRotate_Y(&q1, t)); break;
    }
}

void Session::requireHolds(const char* call, const TQ3BoundingBox& box, const Exact& p)
{
    const Exact low = exactPoint(box.min), high = exactPoint(box.max);
    if (finite(low) && finite(high) && finite(p))
        require(low.x <= p.x && p.x <= high.x && low.y <= p.y && p.y <= high.y && low.z <= p.z && p.z <= high.z,
                call, "the box does not hold a point it was made of");
}

void Session::requireHolds(const char* call, const TQ3BoundingSphere& sphere, const Exact& p)
{
    const double dx = p.x - sphere.origin.x, dy = p.y - sphere.origin.y, dz = p.z - sphere.origin.z;
    const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (std::isfinite(d) && std::isfinite(sphere.radius))
        require(d <= double(sphere.radius) * (1.0 + 1e-12), call,
                "the sphere does not hold a point it was made of");
}

void Session::mathBounds(bool nullArg)
{
    TQ3BoundingBox box1{point3(), point3(), kQ3False}, box2{point3(), point3(), kQ3False};
    TQ3BoundingSphere s1{point3(), m_in.value(), kQ3False}, s2{point3(), m_in.value(), kQ3False};
    setIsEmpty(box1);
    setIsEmpty(box2);
    setIsEmpty(s1);
    setIsEmpty(s2);
    const TQ3Point3D point = point3();
    const TQ3RationalPoint4D point4D = point4();
    // Passed from C (CCaller.c): C++ cannot hold an int outside the enum.
    const int isEmpty = m_in.u8() % 4 == 0 ? static_cast<int>(m_in.u32()) : m_in.u8() % 2;
    const bool box1Empty = enumInt(box1.isEmpty) != 0;
    // A sphere with a negative radius holds nothing the union could keep.
    const bool s1Sane = enumInt(s1.isEmpty) != 0 || s1.radius >= 0.0f;
    const TQ3BoundingBox box1Before = box1;
    switch (m_in.u8() % 12) {
    case 0: MATH_INTO(&box2, Q3BoundingBox_Copy(&box1, nullArg ? nullptr : &box2)); break;
    case 1: MATH_INTO(&box1, Q3BoundingBox_Union(&box1, nullArg ? nullptr : &box2, &box1)); break;
    case 2: MATH_INTO(&box1, q3fuzz_BoundingBox_Set(&box1, &point, nullArg ? nullptr : &point, isEmpty)); break;
    case 3:
        if (MATH_INTO(&box1, Q3BoundingBox_UnionPoint3D(&box1, &point, &box1)))
            requireHolds("Q3BoundingBox_UnionPoint3D", box1, exactPoint(point));
        break;
    case 4:
        if (MATH_INTO(&box1, Q3BoundingBox_UnionRationalPoint4D(&box1, &point4D, &box1)))
            requireHolds("Q3BoundingBox_UnionRationalPoint4D", box1, exactPoint(point4D));
        break;
    case 5: MATH_INTO(&s2, Q3BoundingSphere_Copy(&s1, &s2)); break;
    case 6: MATH_INTO(&s1, Q3BoundingSphere_Union(&s1, nullArg ? nullptr : &s2, &s1)); break;
    case 7:
        MATH_INTO(&s1, q3fuzz_BoundingSphere_Set(&s1, nullArg ? nullptr : &point, m_in.value(), isEmpty));
        break;
    case 8:
        if (MATH_INTO(&s1, Q3BoundingSphere_UnionPoint3D(&s1, &point, nullArg ? nullptr : &s1)) && s1Sane)
            requireHolds("Q3BoundingSphere_UnionPoint3D", s1, exactPoint(point));
        break;
    case 9:
        if (MATH_INTO(&s1, Q3BoundingSphere_UnionRationalPoint4D(&s1, &point4D, &s1)) && s1Sane)
            requireHolds("Q3BoundingSphere_UnionRationalPoint4D", s1, exactPoint(point4D));
        break;
    case 10:
        // A box that is not empty (nor inside out) still holds its
        // corners after a union.
        if (MATH_INTO(&box2, Q3BoundingBox_Union(&box2, &box1, &box2)) && !box1Empty &&
            box1Before.min.x <= box1Before.max.x && box1Before.min.y <= box1Before.max.y &&
            box1Before.min.z <= box1Before.max.z) {
            requireHolds("Q3BoundingBox_Union", box2, exactPoint(box1Before.min));
            requireHolds("Q3BoundingBox_Union", box2, exactPoint(box1Before.max));
        }
        break;
    default: MATH_INTO(&box2, Q3BoundingBox_Copy(&box2, &box2)); break;
    }
}

TQ3Point3D Session::transformedOnce(const TQ3Point3D& p, const TQ3Matrix4x4& m)
{
    TQ3Point3D r{};
    POINTER(Q3Point3D_Transform(&p, &m, &r));
    return r;
}

TQ3RationalPoint4D Session::transformedOnce(const TQ3RationalPoint4D& p, const TQ3Matrix4x4& m)
{
    TQ3RationalPoint4D r{};
    POINTER(Q3RationalPoint4D_Transform(&p, &m, &r));
    return r;
}

void Session::mathArrays(const TQ3Matrix4x4& m, bool nullArg)
{
    const std::uint8_t which = m_in.u8() % 9;
    MathArray<TQ3Point3D> in3 = readMathArray<TQ3Point3D>([&] { return point3(); });
    MathArray<TQ3RationalPoint4D> in4 = readMathArray<TQ3RationalPoint4D>([&] { return point4(); });
    MathArray<TQ3Point3D> out3 = readMathArray<TQ3Point3D>([&] { return point3(); });
    MathArray<TQ3RationalPoint4D> out4 = readMathArray<TQ3RationalPoint4D>([&] { return point4(); });
    // The outputs hold as many elements as the inputs claim (a claim
    // no array could hold is rejected before anything is written).
    for (const unsigned long n : {in3.badCount ? 0 : in3.count, in4.badCount ? 0 : in4.count}) {
        out3.reserveFor(n);
        out4.reserveFor(n);
    }
    out3.count = out4.count = 0;
    const bool negative = m_in.u8() == 255;
    auto countOf = [&](const auto& in) {
        return negative ? -1 - long(m_in.u8()) : long(std::min(in.count, kLongMax));
    };
    const TQ3Matrix4x4* matrix = nullArg ? nullptr : &m;
    auto transformOf = [&](const auto& p) { return transformedOnce(p, m); };
    auto rationalOf = [&](const TQ3Point3D& p) {
        const TQ3RationalPoint4D r{p.x, p.y, p.z, 1.0f};
        return transformedOnce(r, m);
    };
    TQ3BoundingBox box{};
    TQ3BoundingSphere sphere{};
    switch (which) {
    case 0: {
        const long count = countOf(in3);
        transformArray("Q3Point3D_To3DTransformArray", in3, out3, count, [&] {
            return Q3Point3D_To3DTransformArray(in3.data(), matrix, out3.data(), count, in3.stride, out3.stride);
        }, transformOf);
        break;
    }
    case 1: {
        const long count = countOf(in3);
        transformArray("Q3Point3D_To4DTransformArray", in3, out4, count, [&] {
            return Q3Point3D_To4DTransformArray(in3.data(), matrix, out4.data(), count, in3.stride, out4.stride);
        }, rationalOf);
        break;
    }
    case 2: {
        const long count = countOf(in4);
        transformArray("Q3RationalPoint4D_To4DTransformArray", in4, out4, count, [&] {
            return Q3RationalPoint4D_To4DTransformArray(in4.data(), matrix, out4.data(), count, in4.stride,
                                                        out4.stride);
        }, transformOf);
        break;
    }
    case 3: {
        // In place: the input array is the output array.
        const long count = countOf(in3);
        transformArray("Q3Point3D_To3DTransformArray", in3, in3, count, [&] {
            return Q3Point3D_To3DTransformArray(in3.data(), matrix, in3.data(), count, in3.stride, in3.stride);
        }, transformOf);
        break;
    }
    case 4:
        boundOfArray("Q3BoundingBox_SetFromPoints3D", nullArg ? nullptr : &box, in3,
                     &Q3BoundingBox_SetFromPoints3D);
        break;
    case 5:
        boundOfArray("Q3BoundingBox_SetFromRationalPoints4D", nullArg ? nullptr : &box, in4,
                     &Q3BoundingBox_SetFromRationalPoints4D);
        break;
    case 6:
        boundOfArray("Q3BoundingSphere_SetFromPoints3D", nullArg ? nullptr : &sphere, in3,
                     &Q3BoundingSphere_SetFromPoints3D);
        break;
    case 7:
        boundOfArray("Q3BoundingSphere_SetFromRationalPoints4D", nullArg ? nullptr : &sphere, in4,
                     &Q3BoundingSphere_SetFromRationalPoints4D);
        break;
    default: {
        // Contiguous points and weights, as many as claimed, or a count
        // no array could hold.
        std::vector<TQ3Point3D> points(m_in.u8() % 6);
        std::vector<float> weights(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            points[i] = point3();
            weights[i] = m_in.value();
        }
        unsigned long n = points.size();
        if (m_in.u8() == 255)
            n = std::numeric_limits<unsigned long>::max() - m_in.u8();
        TQ3Point3D result = point3();
        MATH_INTO(&result, Q3Point3D_AffineComb(points.empty() ? nullptr : points.data(),
                                                weights.empty() ? nullptr : weights.data(), n,
                                                nullArg ? nullptr : &result));
        break;
    }
    }
}

} // namespace q3fuzz
