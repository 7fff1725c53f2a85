// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The API fuzzer's operations on NURB curves, the curve tools and NURB patches.

#include "FuzzSession.h"

namespace q3fuzz {

void Session::newCurve()
{
    CurveBuffers c;
    readCurve(c);
    const TQ3Object curve = OBJECT(Q3NURBCurve_New(&c.data));
    if (curve == nullptr)
        return;
    hold(curve, Kind::kCurve);
    m_curves[curve] = CurveShape{c.data.order, c.data.numPoints};
    verifyCurve(curve, c.data);
}

void Session::curveSetData()
{
    const TQ3Object curve = pick(Kind::kCurve);
    CurveBuffers c;
    readCurve(c);
    const bool isCurve = holdsKind(curve, Kind::kCurve) && m_initialized > 0;
    const unsigned long before = isCurve ? editIndex(curve) : 0;
    const bool nullData = m_in.u8() == 0;
    if (STATUS(Q3NURBCurve_SetData(curve, nullData ? nullptr : &c.data)) == kQ3Success) {
        require(isCurve, "Q3NURBCurve_SetData", "accepted something that is not a held curve");
        require(editIndex(curve) != before, "Q3NURBCurve_SetData", "did not change the edit index");
        m_curves[curve] = CurveShape{c.data.order, c.data.numPoints};
        verifyCurve(curve, c.data);
    } else if (isCurve) {
        require(editIndex(curve) == before, "Q3NURBCurve_SetData", "failed but changed the edit index");
    }
}

void Session::curveGetData()
{
    const TQ3Object curve = pick(Kind::kCurve);
    const bool nullData = m_in.u8() == 0;
    TQ3NURBCurveData data;
    std::memset(&data, 0xA5, sizeof data);
    TQ3NURBCurveData untouched = data;
    if (STATUS(Q3NURBCurve_GetData(curve, nullData ? nullptr : &data)) == kQ3Success) {
        const auto shape = m_curves.find(curve);
        require(shape != m_curves.end(), "Q3NURBCurve_GetData", "succeeded on something that is not a curve");
        require(data.order == shape->second.order && data.numPoints == shape->second.numPoints,
                "Q3NURBCurve_GetData", "order or numPoints changed behind the caller's back");
        STATUS(Q3NURBCurve_EmptyData(&data));
        // Emptying again does nothing and succeeds.
        if (STATUS(Q3NURBCurve_EmptyData(&data)) != kQ3Success)
            die("Q3NURBCurve_EmptyData", "failed on emptied data");
    } else {
        require(sameBytes(data, untouched), "Q3NURBCurve_GetData", "failed but wrote its output");
    }
    if (m_in.u8() == 0)
        STATUS(Q3NURBCurve_EmptyData(nullptr));
}

unsigned long Session::knotCount(TQ3Object curve) const
{
    const auto shape = m_curves.find(curve);
    return shape == m_curves.end() ? 8 : shape->second.numPoints + shape->second.order;
}

unsigned long Session::pointCount(TQ3Object curve) const
{
    const auto shape = m_curves.find(curve);
    return shape == m_curves.end() ? 4 : shape->second.numPoints;
}

bool Session::inRangeOfHeldCurve(TQ3Object curve, unsigned long index, unsigned long count) const
{
    return m_initialized > 0 && m_curves.count(curve) != 0 && index < count;
}

void Session::setKnot()
{
    const TQ3Object curve = pick(Kind::kCurve);
    const unsigned long count = knotCount(curve);
    const unsigned long index = m_in.index(count);
    const float value = m_in.value();
    const bool known = inRangeOfHeldCurve(curve, index, count);
    float old = 0.0f;
    unsigned long before = 0;
    if (known) {
        before = editIndex(curve);
        STATUS(Q3NURBCurve_GetKnot(curve, index, &old));
    }
    if (STATUS(Q3NURBCurve_SetKnot(curve, index, value)) == kQ3Success) {
        require(known, "Q3NURBCurve_SetKnot", "succeeded on an index or object it should reject");
        float now = 0.0f;
        STATUS(Q3NURBCurve_GetKnot(curve, index, &now));
        require(sameBytes(now, value), "Q3NURBCurve_SetKnot", "the knot does not read back");
        require(editIndex(curve) != before, "Q3NURBCurve_SetKnot", "did not change the edit index");
    } else if (known) {
        float now = 0.0f;
        STATUS(Q3NURBCurve_GetKnot(curve, index, &now));
        require(sameBytes(now, old), "Q3NURBCurve_SetKnot", "failed but changed the knot");
        require(editIndex(curve) == before, "Q3NURBCurve_SetKnot", "failed but changed the edit index");
    }
}

void Session::getKnot()
{
    const TQ3Object curve = pick(Kind::kCurve);
    const unsigned long count = knotCount(curve);
    const unsigned long index = m_in.index(count);
    const bool nullOut = m_in.u8() == 0;
    float value = -12345.0f;
    const TQ3Status status = STATUS(Q3NURBCurve_GetKnot(curve, index, nullOut ? nullptr : &value));
    if (inRangeOfHeldCurve(curve, index, count) && !nullOut)
        require(status == kQ3Success, "Q3NURBCurve_GetKnot", "failed on a valid index");
    if (status == kQ3Failure)
        require(value == -12345.0f, "Q3NURBCurve_GetKnot", "failed but wrote its output");
}

void Session::setControlPoint()
{
    const TQ3Object curve = pick(Kind::kCurve);
    const unsigned long count = pointCount(curve);
    const unsigned long index = m_in.index(count);
    const TQ3RationalPoint4D point{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
    const bool nullPoint = m_in.u8() == 0;
    const bool known = inRangeOfHeldCurve(curve, index, count);
    TQ3RationalPoint4D old{};
    unsigned long before = 0;
    if (known) {
        before = editIndex(curve);
        STATUS(Q3NURBCurve_GetControlPoint(curve, index, &old));
    }
    if (STATUS(Q3NURBCurve_SetControlPoint(curve, index, nullPoint ? nullptr : &point)) == kQ3Success) {
        require(known, "Q3NURBCurve_SetControlPoint", "succeeded on an index or object it should reject");
        TQ3RationalPoint4D now{};
        STATUS(Q3NURBCurve_GetControlPoint(curve, index, &now));
        require(sameBytes(now, point), "Q3NURBCurve_SetControlPoint", "the point does not read back");
        require(editIndex(curve) != before, "Q3NURBCurve_SetControlPoint", "did not change the edit index");
    } else if (known) {
        TQ3RationalPoint4D now{};
        STATUS(Q3NURBCurve_GetControlPoint(curve, index, &now));
        require(sameBytes(now, old), "Q3NURBCurve_SetControlPoint", "failed but changed the point");
        require(editIndex(curve) == before, "Q3NURBCurve_SetControlPoint", "failed but changed the edit index");
    }
}

void Session::getControlPoint()
{
    const TQ3Object curve = pick(Kind::kCurve);
    const unsigned long count = pointCount(curve);
    const unsigned long index = m_in.index(count);
    const bool nullOut = m_in.u8() == 0;
    TQ3RationalPoint4D point{-1, -2, -3, -4};
    const TQ3RationalPoint4D untouched = point;
    const TQ3Status status =
        STATUS(Q3NURBCurve_GetControlPoint(curve, index, nullOut ? nullptr : &point));
    if (inRangeOfHeldCurve(curve, index, count) && !nullOut)
        require(status == kQ3Success, "Q3NURBCurve_GetControlPoint", "failed on a valid index");
    if (status == kQ3Failure)
        require(sameBytes(point, untouched), "Q3NURBCurve_GetControlPoint", "failed but wrote its output");
}

void Session::readPatch(PatchBuffers& p)
{
    const std::uint8_t flags = m_in.u8();
    const unsigned long uOrder = (flags & 1) ? m_in.u32() : 1 + m_in.u8() % 12;
    const unsigned long vOrder = (flags & 2) ? m_in.u32() : 1 + m_in.u8() % 12;
    // Arrays are sized with orders Q3 accepts, whatever the fields say.
    const unsigned long au = std::clamp<unsigned long>(uOrder, 2, kQ3NURBPatchMaxOrder);
    const unsigned long av = std::clamp<unsigned long>(vOrder, 2, kQ3NURBPatchMaxOrder);
    const unsigned long columns = au + m_in.u8() % 6, rows = av + m_in.u8() % 6;
    takePoints(rows * columns, rows * columns);
    const std::uint8_t shape = m_in.u8();
    const float scale = m_in.value();
    p.points.resize(rows * columns);
    for (unsigned long r = 0; r < rows; ++r)
        for (unsigned long c = 0; c < columns; ++c) {
            const float w = (shape & 1) ? 1.0f + float((r + c) % 3) : 1.0f;
            const float x = float(c) / float(columns - 1) * scale, y = float(r) / float(rows - 1) * scale;
            const float z = (shape & 2) ? std::sin(float(r + 2 * c)) * scale : 0.25f * float((r + c) % 2);
            p.points[r * columns + c] = TQ3RationalPoint4D{x * w, y * w, z * w, w};
        }
    p.uKnots = clampedKnots(columns, au, shape & 4);
    p.vKnots = clampedKnots(rows, av, shape & 8);
    for (int n = m_in.u8() % 8; n > 0; --n) {
        const std::uint8_t target = m_in.u8();
        const float v = m_in.value();
        if ((target & 3) == 1)
            p.uKnots[m_in.u16() % p.uKnots.size()] = v;
        else if ((target & 3) == 2)
            p.vKnots[m_in.u16() % p.vKnots.size()] = v;
        else
            (&p.points[m_in.u16() % p.points.size()].x)[target >> 6] = v;
    }
    // Trim loops: each a circle (or, reversed, a hole) around a point of
    // the domain, cut into curves that join end to end; optionally left
    // open, or with values overwritten.
    const float width = float(columns - au + 1), height = float(rows - av + 1);
    const unsigned long loopCount = m_in.u8() % 5;
    p.trimPoints.clear();
    p.curves.resize(loopCount);
    for (unsigned long l = 0; l < loopCount; ++l) {
        const std::uint8_t loopFlags = m_in.u8();
        const unsigned long curveCount = m_in.u8() % 4;
        const float cu = float(m_in.u8()) / 255.0f * width, cv = float(m_in.u8()) / 255.0f * height;
        const float radius = float(1 + m_in.u8()) / 512.0f * std::min(width, height);
        const float turn = (loopFlags & 1) ? -1.0f : 1.0f;
        for (unsigned long k = 0; k < curveCount; ++k) {
            const unsigned long order = (loopFlags & 2) ? m_in.u32() : 1 + m_in.u8() % 6;
            const unsigned long arrayOrder = std::clamp<unsigned long>(order, 2, 16);
            const unsigned long count = arrayOrder + m_in.u8() % 4;
            takePoints(count, count);
            std::vector<TQ3RationalPoint3D> points(count);
            for (unsigned long i = 0; i < count; ++i) {
                const float a = 6.2831853f * turn * (float(k) + float(i) / float(count - 1)) / float(curveCount);
                const float w = (loopFlags & 4) ? 1.0f + 0.5f * float(i % 2) : 1.0f;
                points[i] = {(cu + radius * std::cos(a)) * w, (cv + radius * std::sin(a)) * w, w};
            }
            if (k + 1 == curveCount) // exactly where the first curve starts
                points[count - 1] = {cu + radius, cv, 1.0f};
            p.trimPoints.push_back(std::move(points));
            p.trimKnots.push_back(clampedKnots(count, arrayOrder, loopFlags & 8));
            TQ3NURBPatchTrimCurveData curve{};
            curve.order = order;
            curve.numPoints = count;
            p.curves[l].push_back(curve);
        }
        if ((loopFlags & 16) && curveCount > 0) // open
            p.trimPoints.back().back().x += 0.25f * radius;
        if (loopFlags & 32)
            for (int n = m_in.u8() % 4; n > 0; --n) {
                const float v = m_in.value();
                if (p.trimPoints.empty())
                    break;
                std::vector<TQ3RationalPoint3D>& points = p.trimPoints[m_in.u8() % p.trimPoints.size()];
                (&points[m_in.u8() % points.size()].x)[m_in.u8() % 3] = v;
            }
        if ((loopFlags & 64) && !p.trimKnots.empty())
            p.trimKnots.back()[m_in.u8() % p.trimKnots.back().size()] = m_in.value();
    }
    // Pointers, once every array is in place.
    std::size_t next = 0;
    p.loops.resize(loopCount);
    for (unsigned long l = 0; l < loopCount; ++l) {
        for (TQ3NURBPatchTrimCurveData& curve : p.curves[l]) {
            curve.controlPoints = p.trimPoints[next].data();
            curve.knots = p.trimKnots[next].data();
            ++next;
        }
        p.loops[l].numTrimCurves = p.curves[l].size();
        p.loops[l].trimCurves = p.curves[l].empty() ? nullptr : p.curves[l].data();
        if (m_in.u8() == 0xFF)
            p.loops[l].numTrimCurves = ~0UL - m_in.u8();
    }
    p.data.uOrder = uOrder;
    p.data.vOrder = vOrder;
    p.data.numRows = (flags & 8) ? ~0UL - m_in.u8() : rows;
    p.data.numColumns = (flags & 16) ? (m_in.u8() & 1 ? ~0UL : 1UL << 32) : columns;
    p.data.controlPoints = (flags & 64) ? nullptr : p.points.data();
    p.data.uKnots = (flags & 128) ? nullptr : p.uKnots.data();
    p.data.vKnots = (flags & 128) ? nullptr : p.vKnots.data();
    p.data.numTrimLoops = (flags & 4) ? ~0UL - m_in.u8() : loopCount;
    p.data.trimLoops = p.loops.empty() ? nullptr : p.loops.data();
    p.data.patchAttributeSet = (flags & 32) ? pick(Kind::kAttributeSet) : nullptr;
}

void Session::patches()
{
    const std::uint8_t action = m_in.u8() % 7;
    if (action <= 3) {
        PatchBuffers p;
        readPatch(p);
        const bool nullData = m_in.u8() == 0;
        if (action == 3 && !drawAllowed())
            return;
        surfaceAction<TQ3NURBPatchData>(action, Kind::kPatch, nullData ? nullptr : &p.data, Q3NURBPatch_New,
                                        Q3NURBPatch_SetData, Q3NURBPatch_GetData, Q3NURBPatch_EmptyData,
                                        Q3NURBPatch_Submit, samePatch);
        return;
    }
    if (action == 4)
        return patchField();
    const TQ3Object patch = pick(Kind::kPatch);
    const TQ3Object view = pick(Kind::kView);
    if (!drawAllowed())
        return;
    const DrawTimer timer(m_drawSeconds);
    if (action == 5) {
        // pick may give another kind: a primitive decomposes to NULL silently.
        const Held* picked = heldEntry(patch);
        if (picked != nullptr && isPrimitiveKind(picked->kind)) {
            checkDecomposition(patch, view);
            return;
        }
        const TQ3Object result = OBJECT(Q3Geometry_GetDecomposed(patch, view));
        if (result == nullptr)
            return;
        const Held* entry = heldEntry(patch);
        require(entry != nullptr, "Q3Geometry_GetDecomposed", "decomposed something nobody holds");
        if (entry->kind == Kind::kPatch)
            checkPatchDecomposed(patch, result);
        else // another geometry, picked when no patch is held
            hold(result, Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh ? Kind::kTriMesh : Kind::kPolyLine);
    } else {
        STATUS(Q3Geometry_Submit(patch, view));
    }
}

void Session::patchField()
{
    const TQ3Object patch = pick(Kind::kPatch);
    const bool ours = holdsKind(patch, Kind::kPatch) && m_initialized > 0;
    TQ3NURBPatchData shape{};
    if (ours && STATUS(Q3NURBPatch_GetData(patch, &shape)) != kQ3Success)
        die("Q3NURBPatch_GetData", "failed on a live patch");
    const std::uint8_t field = m_in.u8();
    const bool set = field & 1, nullArg = m_in.u8() == 0;
    const unsigned long row = m_in.index(shape.numRows), column = m_in.index(shape.numColumns);
    const unsigned long uKnot = m_in.index(shape.uOrder + shape.numColumns);
    const unsigned long vKnot = m_in.index(shape.vOrder + shape.numRows);
    const TQ3RationalPoint4D point{m_in.value(), m_in.value(), m_in.value(), m_in.value()};
    const float knot = m_in.value();
    const unsigned long before = ours ? editIndex(patch) : 0;
    TQ3Status status = kQ3Failure;
    switch ((field >> 1) % 3) {
    case 0:
        if (set) {
            status = STATUS(Q3NURBPatch_SetControlPoint(patch, row, column, nullArg ? nullptr : &point));
            TQ3RationalPoint4D got{};
            if (status == kQ3Success && ours &&
                STATUS(Q3NURBPatch_GetControlPoint(patch, row, column, &got)) == kQ3Success)
                require(sameBytes(got, point), "Q3NURBPatch_SetControlPoint", "does not read back");
        } else {
            TQ3RationalPoint4D got{};
            status = STATUS(Q3NURBPatch_GetControlPoint(patch, row, column, nullArg ? nullptr : &got));
            if (ours && !nullArg && row < shape.numRows && column < shape.numColumns)
                require(status == kQ3Success && sameBytes(got, shape.controlPoints[row * shape.numColumns + column]),
                        "Q3NURBPatch_GetControlPoint", "failed or differs from GetData on a valid index");
        }
        break;
    case 1:
    case 2: {
        const bool inU = (field >> 1) % 3 == 1;
        const unsigned long index = inU ? uKnot : vKnot;
        auto setKnot = inU ? Q3NURBPatch_SetUKnot : Q3NURBPatch_SetVKnot;
        auto getKnot = inU ? Q3NURBPatch_GetUKnot : Q3NURBPatch_GetVKnot;
        const unsigned long count = inU ? shape.uOrder + shape.numColumns : shape.vOrder + shape.numRows;
        float got = 0.0f;
        if (set) {
            status = STATUS(setKnot(patch, index, knot));
            if (status == kQ3Success && ours && STATUS(getKnot(patch, index, &got)) == kQ3Success)
                require(sameBytes(got, knot), "Q3NURBPatch_SetKnot", "does not read back");
        } else {
            status = STATUS(getKnot(patch, index, nullArg ? nullptr : &got));
            if (ours && !nullArg && index < count)
                require(status == kQ3Success && sameBytes(got, (inU ? shape.uKnots : shape.vKnots)[index]),
                        "Q3NURBPatch_GetKnot", "failed or differs from GetData on a valid index");
        }
        break;
    }
    }
    require(status == kQ3Failure || ours, "Q3NURBPatch_*", "succeeded on something that is not a patch");
    if (ours) {
        if (set && status == kQ3Failure) {
            TQ3NURBPatchData now{};
            STATUS(Q3NURBPatch_GetData(patch, &now));
            require(editIndex(patch) == before && samePatch(now, shape), "Q3NURBPatch_Set",
                    "failed but changed the patch");
            STATUS(Q3NURBPatch_EmptyData(&now));
        }
        STATUS(Q3NURBPatch_EmptyData(&shape));
    }
}

void Session::checkPatchDecomposed(TQ3Object patch, TQ3Object result)
{
    const char* call = "Q3Geometry_GetDecomposed";
    require(Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh, call, "a patch gave no trimesh");
    hold(result, Kind::kTriMesh);
    TQ3NURBPatchData data{};
    STATUS(Q3NURBPatch_GetData(patch, &data));
    const unsigned long spans = (data.numColumns - data.uOrder + 1) * (data.numRows - data.vOrder + 1);
    STATUS(Q3NURBPatch_EmptyData(&data));
    TQ3TriMeshData mesh{};
    STATUS(Q3TriMesh_GetData(result, &mesh));
    require(mesh.numTriangles <= std::max<unsigned long>(kQ3SubdivisionMaxTrianglesPerPatch, 2 * spans), call,
            "a patch's trimesh has more triangles than the cap");
    for (unsigned long i = 0; i < mesh.numPoints; ++i)
        require(std::isfinite(mesh.points[i].x) && std::isfinite(mesh.points[i].y) &&
                    std::isfinite(mesh.points[i].z),
                call, "a patch's trimesh has a point that is not finite");
    for (unsigned long t = 0; t < mesh.numTriangles; ++t)
        for (unsigned long k : mesh.triangles[t].pointIndices)
            require(k < mesh.numPoints, call, "a patch's trimesh has an index out of range");
    STATUS(Q3TriMesh_EmptyData(&mesh));
}

void Session::quadricDecompose(Kind kind)
{
    const TQ3Object geometry = pick(kind);
    const TQ3Object view = pick(Kind::kView);
    if (!drawAllowed())
        return;
    checkDecomposition(geometry, view);
}

namespace {

// Whether a quadric is clearly not degenerate by QD3DGeometry.h's tests
// (dependent vectors: |x . (y x z)| <= 1e-6 |x| |y| |z|, |x x y| <= 1e-6
// |x| |y|; an empty range; a torus's ratio of 0), with margins: vectors of
// lengths far from float's limits, products above 1e-4 of the lengths',
// ranges at least 1e-4 wide and not 1 to 0, a ratio above 1e-4. Computed
// in double, from the header's formulas.
double length(const TQ3Vector3D& v)
{
    return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

bool moderate(const TQ3Vector3D& v)
{
    const double l = length(v);
    return l > 1e-10 && l < 1e10;
}

bool moderate(const TQ3Point3D& p)
{
    return moderate(TQ3Vector3D{p.x, p.y, p.z}) || (p.x == 0.0f && p.y == 0.0f && p.z == 0.0f);
}

struct Cross {
    double x, y, z;
};

Cross cross(const TQ3Vector3D& a, const TQ3Vector3D& b)
{
    return Cross{double(a.y) * b.z - double(a.z) * b.y, double(a.z) * b.x - double(a.x) * b.z,
                 double(a.x) * b.y - double(a.y) * b.x};
}

bool clearlyIndependent(const TQ3Vector3D& a, const TQ3Vector3D& b)
{
    const Cross c = cross(a, b);
    return moderate(a) && moderate(b) && std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z) > 1e-4 * length(a) * length(b);
}

bool clearlyIndependent(const TQ3Vector3D& a, const TQ3Vector3D& b, const TQ3Vector3D& c)
{
    const Cross bc = cross(b, c);
    const double triple = a.x * bc.x + a.y * bc.y + a.z * bc.z;
    return moderate(a) && moderate(b) && moderate(c) && std::fabs(triple) > 1e-4 * length(a) * length(b) * length(c);
}

bool clearlyNonEmpty(float low, float high)
{
    return std::fabs(double(high) - low) > 1e-4 && !(std::fabs(low - 1.0) < 1e-4 && std::fabs(double(high)) < 1e-4);
}

bool clearlyDrawable(const TQ3BoxData& d)
{
    return moderate(d.origin) && clearlyIndependent(d.orientation, d.majorAxis, d.minorAxis);
}

template <class D>
bool clearlyDrawableSolid(const D& d)
{
    return moderate(d.origin) && clearlyIndependent(d.orientation, d.majorRadius, d.minorRadius) &&
           clearlyNonEmpty(d.uMin, d.uMax) && clearlyNonEmpty(d.vMin, d.vMax);
}
bool clearlyDrawable(const TQ3ConeData& d) { return clearlyDrawableSolid(d); }
bool clearlyDrawable(const TQ3CylinderData& d) { return clearlyDrawableSolid(d); }
bool clearlyDrawable(const TQ3EllipsoidData& d) { return clearlyDrawableSolid(d); }
bool clearlyDrawable(const TQ3TorusData& d) { return clearlyDrawableSolid(d) && d.ratio > 1e-4f; }

bool clearlyDrawable(const TQ3DiskData& d)
{
    return moderate(d.origin) && clearlyIndependent(d.majorRadius, d.minorRadius) &&
           clearlyNonEmpty(d.uMin, d.uMax) && clearlyNonEmpty(d.vMin, d.vMax);
}

} // namespace

template <class Data>
bool Session::quadricClearlyDrawable(TQ3Object geometry, TQ3Status (*getData)(TQ3GeometryObject, Data*),
                                     TQ3Status (*emptyData)(Data*))
{
    Data data{};
    if (STATUS(getData(geometry, &data)) != kQ3Success)
        return false;
    const bool drawable = clearlyDrawable(data);
    STATUS(emptyData(&data));
    return drawable;
}

bool Session::quadricClearlyDrawable(TQ3Object geometry, Kind kind)
{
    switch (kind) {
    case Kind::kBox: return quadricClearlyDrawable(geometry, Q3Box_GetData, Q3Box_EmptyData);
    case Kind::kCone: return quadricClearlyDrawable(geometry, Q3Cone_GetData, Q3Cone_EmptyData);
    case Kind::kCylinder: return quadricClearlyDrawable(geometry, Q3Cylinder_GetData, Q3Cylinder_EmptyData);
    case Kind::kDisk: return quadricClearlyDrawable(geometry, Q3Disk_GetData, Q3Disk_EmptyData);
    case Kind::kEllipsoid: return quadricClearlyDrawable(geometry, Q3Ellipsoid_GetData, Q3Ellipsoid_EmptyData);
    case Kind::kTorus: return quadricClearlyDrawable(geometry, Q3Torus_GetData, Q3Torus_EmptyData);
    default: return false;
    }
}

void Session::checkQuadricDecomposed(Kind kind, TQ3Object geometry, TQ3Object result)
{
    const char* call = "Q3Geometry_GetDecomposed";
    if (kind == Kind::kEllipse) {
        // An empty arc (uMin == uMax, or 1 to 0) is nothing: "a TriMesh of
        // no points" (QD3DGeometry.h); any other ellipse is a polyline.
        TQ3EllipseData ellipse{};
        const Posts saved = g_posts;
        const bool emptyArc = Q3Ellipse_GetData(geometry, &ellipse) == kQ3Success &&
                              (ellipse.uMin == ellipse.uMax || (ellipse.uMin == 1.0f && ellipse.uMax == 0.0f));
        if (emptyArc)
            Q3Ellipse_EmptyData(&ellipse);
        g_posts = saved;
        if (emptyArc && Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh) {
            hold(result, Kind::kTriMesh);
            TQ3TriMeshData mesh{};
            STATUS(Q3TriMesh_GetData(result, &mesh));
            require(mesh.numPoints == 0 && mesh.numTriangles == 0, call, "an empty arc gave a trimesh with points");
            STATUS(Q3TriMesh_EmptyData(&mesh));
            return;
        }
        require(Q3Geometry_GetType(result) == kQ3GeometryTypePolyLine, call, "an ellipse gave no polyline");
        hold(result, Kind::kPolyLine);
        TQ3PolyLineData line{};
        STATUS(Q3PolyLine_GetData(result, &line));
        require(line.numVertices >= 2 && line.numVertices <= (unsigned long)kQ3SubdivisionMaxSegmentsPerCurve + 1,
                call, "an ellipse's polyline has the wrong size");
        STATUS(Q3PolyLine_EmptyData(&line));
        return;
    }
    require(Q3Geometry_GetType(result) == kQ3GeometryTypeTriMesh, call, "a shape gave no trimesh");
    hold(result, Kind::kTriMesh);
    TQ3TriMeshData mesh{};
    STATUS(Q3TriMesh_GetData(result, &mesh));
    // A degenerate shape (QD3DGeometry.h: dependent vectors, an empty
    // range, a torus's ratio of 0) "gives a TriMesh of no points".
    require(mesh.numTriangles <= (unsigned long)kQ3SubdivisionMaxTrianglesPerSurface, call,
            "a shape's trimesh has more triangles than the cap");
    require(mesh.numTriangles >= 1 || mesh.numPoints == 0, call, "a shape's trimesh has points but no triangles");
    if (mesh.numTriangles == 0)
        require(!quadricClearlyDrawable(geometry, kind), call, "a shape that is not degenerate drew nothing");
    for (unsigned long i = 0; i < mesh.numPoints; ++i)
        require(std::isfinite(mesh.points[i].x) && std::isfinite(mesh.points[i].y) &&
                    std::isfinite(mesh.points[i].z),
                call, "a shape's trimesh has a point that is not finite");
    STATUS(Q3TriMesh_EmptyData(&mesh));
}

void Session::curveTools()
{
    const bool object = m_in.u8() & 1;
    const TQ3Object curve = object ? pick(Kind::kCurve) : nullptr;
    CurveBuffers c;
    if (!object)
        readCurve(c);
    const TQ3NURBCurveData* data = m_in.u8() == 0 ? nullptr : &c.data;
    const bool nullOut = m_in.u8() == 0;
    const float a = m_in.value();
    const float b = m_in.value();
    const float tolerance = m_in.value();
    const unsigned long index = m_in.index(object ? knotCount(curve) : c.knots.size());
    const unsigned long times = m_in.index(16);
    const std::uint8_t which = m_in.u8() % 17;
    // Up to 31 knots or 63 points, claimed as they are or as a count past the
    // limit (which Q3 must refuse before reading).
    std::vector<float> knots(m_in.u8() % 32);
    for (float& k : knots)
        k = m_in.value();
    std::vector<TQ3Point3D> points(std::min<std::size_t>(m_in.u8() % 64, m_in.remaining() / 3 + 1));
    for (TQ3Point3D& p : points)
        p = point3();
    const bool hugeCount = m_in.u8() == 0;
    const unsigned long claimedKnots = hugeCount ? kQ3NURBCurveToolsMaxPoints + 1 : knots.size();
    const unsigned long claimedPoints = hugeCount ? ~0UL : points.size();
    const unsigned long order = 1 + m_in.u8() % 17;
    const TQ3NURBCurveParameterization how = (m_in.u8() & 1) ? kQ3NURBCurveParameterizationCentripetal
                                                               : kQ3NURBCurveParameterizationChordLength;
    const TQ3Point3D target = point3();
    if (which >= 12 && !drawAllowed())
        return;
    const DrawTimer timer(m_drawSeconds);
    const bool held = object && holdsKind(curve, Kind::kCurve) && m_initialized > 0;
    const unsigned long before = held ? editIndex(curve) : 0;

    struct Outputs {
        float f[2];
        TQ3Point3D p;
        TQ3Vector3D v[2];
        TQ3NURBCurveData curves[2];
        unsigned long n;
    } out, untouched;
    std::memset(&out, 0x5A, sizeof out);
    untouched = out;
    float* f0 = nullOut ? nullptr : &out.f[0];
    TQ3NURBCurveData* c0 = nullOut ? nullptr : &out.curves[0];
    TQ3NURBCurveData* c1 = (m_in.u8() & 7) == 0 ? c0 : &out.curves[1];
#define Q3_FUZZ_TOOL(name, ...)                                                                     \
(object ? STATUS(Q3NURBCurve_##name(curve, __VA_ARGS__)) : STATUS(Q3NURBCurveData_##name(data, __VA_ARGS__)))
    TQ3Status status = kQ3Failure;
    switch (which) {
    case 0: status = Q3_FUZZ_TOOL(GetDomain, f0, &out.f[1]); break;
    case 1: status = Q3_FUZZ_TOOL(Evaluate, a, nullOut ? nullptr : &out.p); break;
    case 2: status = Q3_FUZZ_TOOL(EvaluateDerivatives, a, &out.p, nullOut ? nullptr : &out.v[0], &out.v[1]); break;
    case 3: status = Q3_FUZZ_TOOL(GetTangent, a, nullOut ? nullptr : &out.v[0]); break;
    case 4: status = Q3_FUZZ_TOOL(GetCurvature, a, f0); break;
    case 5: status = Q3_FUZZ_TOOL(InsertKnot, a, times, c0); break;
    case 6: status = Q3_FUZZ_TOOL(RefineKnots, claimedKnots, knots.empty() ? nullptr : knots.data(), c0); break;
    case 7: status = Q3_FUZZ_TOOL(RemoveKnot, index, times, tolerance, c0, &out.n); break;
    case 8: status = Q3_FUZZ_TOOL(ElevateDegree, times, c0); break;
    case 9: status = Q3_FUZZ_TOOL(CountBezierPieces, nullOut ? nullptr : &out.n); break;
    case 10: status = Q3_FUZZ_TOOL(GetBezierPiece, index, c0); break;
    case 11: status = Q3_FUZZ_TOOL(Split, a, c0, c1); break;
    case 12: status = Q3_FUZZ_TOOL(GetArcLength, a, b, tolerance, f0); break;
    case 13: status = Q3_FUZZ_TOOL(GetParameterAtLength, a, b, tolerance, f0); break;
    case 14: status = Q3_FUZZ_TOOL(GetClosestPoint, &target, f0, &out.p); break;
    case 15:
        status = STATUS(Q3NURBCurveData_Interpolate(order, claimedPoints, points.empty() ? nullptr : points.data(),
                                                     how, c0));
        break;
    default:
        status = STATUS(Q3NURBCurveData_Approximate(order, claimedPoints, points.empty() ? nullptr : points.data(),
                                                     times, how, c0));
        break;
    }
#undef Q3_FUZZ_TOOL
    if (status == kQ3Failure) {
        require(sameBytes(out, untouched), "a curve tool", "failed but wrote its output");
    } else {
        for (TQ3NURBCurveData& made : out.curves) {
            if (sameBytes(made, untouched.curves[0]))
                continue;
            require(made.curveAttributeSet == nullptr, "a curve tool", "handed out an attribute set");
            const TQ3Object check = OBJECT(Q3NURBCurve_New(&made));
            require(check != nullptr, "a curve tool", "handed out a curve Q3NURBCurve_New rejects");
            STATUS(Q3Object_Dispose(check));
            STATUS(Q3NURBCurve_EmptyData(&made));
        }
    }
    if (held)
        require(editIndex(curve) == before, "a curve tool", "changed the retained curve's edit index");
}

TQ3CameraData Session::readCameraData()
{
    TQ3CameraData data{};
    data.placement = {{1.5f, 0.5f, 10.0f}, {1.5f, 0.5f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    data.range = {1.0f, 100.0f};
    data.viewPort = {{-1.0f, 1.0f}, 2.0f, 2.0f};
    const std::uint8_t mode = m_in.u8();
    if (mode & 1) {
        data.placement = {point3(), point3(), vector3()};
        data.range = {m_in.value(), m_in.value()};
        data.viewPort = {{m_in.value(), m_in.value()}, m_in.value(), m_in.value()};
    } else {
        float* values = &data.placement.cameraLocation.x;
        constexpr int kFloats = sizeof(TQ3CameraData) / sizeof(float);
        for (int n = (mode >> 1) % 4; n > 0; --n)
            values[m_in.u8() % kFloats] = m_in.value();
    }
    return data;
}

} // namespace q3fuzz
