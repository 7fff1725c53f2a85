// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The API fuzzer's operations on the other geometries: polygons, quadrics, markers, textures and meshes.

#include "FuzzSession.h"

namespace q3fuzz {

void Session::otherGeometry()
{
    switch (m_in.u8() % 3) {
    case 0: newDescribed<TQ3PointData>(Kind::kPoint, Q3Point_New, Q3Point_GetData, Q3Point_EmptyData, Q3Point_Submit); break;
    case 1: newDescribed<TQ3LineData>(Kind::kLine, Q3Line_New, Q3Line_GetData, Q3Line_EmptyData, Q3Line_Submit); break;
    default:
        newDescribed<TQ3PolyLineData>(Kind::kPolyLine, Q3PolyLine_New, Q3PolyLine_GetData, Q3PolyLine_EmptyData,
                                      Q3PolyLine_Submit);
        break;
    }
}

void Session::accessors()
{
    const bool nullArg = m_in.u8() == 0;
    const bool set = m_in.u8() & 1;
    const TQ3AttributeSet attributes = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
    TQ3AttributeSet got = nullptr;
    TQ3AttributeSet* out = nullArg ? nullptr : &got;
    TQ3Point3D position = point3();
    TQ3Point3D* where = nullArg ? nullptr : &position;
    switch (m_in.u8() % 8) {
    case 0: {
        const TQ3Object point = pick(Kind::kPoint);
        set ? STATUS(Q3Point_SetPosition(point, where)) : STATUS(Q3Point_GetPosition(point, where));
        break;
    }
    case 1: {
        const TQ3Object line = pick(Kind::kLine);
        const unsigned long index = m_in.index(2);
        set ? STATUS(Q3Line_SetVertexPosition(line, index, where))
            : STATUS(Q3Line_GetVertexPosition(line, index, where));
        break;
    }
    case 2: {
        const TQ3Object line = pick(Kind::kLine);
        const unsigned long index = m_in.index(2);
        set ? STATUS(Q3Line_SetVertexAttributeSet(line, index, attributes))
            : STATUS(Q3Line_GetVertexAttributeSet(line, index, out));
        break;
    }
    case 3: {
        const TQ3Object polyLine = pick(Kind::kPolyLine);
        const unsigned long index = m_in.index(8);
        set ? STATUS(Q3PolyLine_SetVertexPosition(polyLine, index, where))
            : STATUS(Q3PolyLine_GetVertexPosition(polyLine, index, where));
        break;
    }
    case 4: {
        const TQ3Object polyLine = pick(Kind::kPolyLine);
        const unsigned long index = m_in.index(8);
        if (m_in.u8() & 1)
            set ? STATUS(Q3PolyLine_SetSegmentAttributeSet(polyLine, index, attributes))
                : STATUS(Q3PolyLine_GetSegmentAttributeSet(polyLine, index, out));
        else
            set ? STATUS(Q3PolyLine_SetVertexAttributeSet(polyLine, index, attributes))
                : STATUS(Q3PolyLine_GetVertexAttributeSet(polyLine, index, out));
        break;
    }
    case 5: {
        static const Kind kGeometries[] = {Kind::kCurve,    Kind::kPolyLine, Kind::kLine,   Kind::kPoint,
                                           Kind::kTriangle, Kind::kPolygon,  Kind::kTriMesh};
        const TQ3Object geometry = pick(kGeometries[m_in.u8() % 7]);
        set ? STATUS(Q3Geometry_SetAttributeSet(geometry, attributes))
            : STATUS(Q3Geometry_GetAttributeSet(geometry, out));
        break;
    }
    case 6:
        transformField(set, nullArg);
        break;
    default:
        cameraField(set, nullArg);
        break;
    }
    if (got != nullptr)
        hold(got, Kind::kAttributeSet);
}

void Session::transformField(bool set, bool nullArg)
{
    const TQ3Object transform = pick(Kind::kTransform);
    TQ3Matrix4x4 matrix = readMatrix();
    TQ3Vector3D vector = vector3();
    TQ3RotateTransformData rotate{};
    const std::int32_t rawAxis = enumValue(3);
    setRaw(rotate.axis, rawAxis);
    rotate.radians = m_in.value();
    TQ3Axis axisOut{};
    float radians = rotate.radians;
    switch (m_in.u8() % 7) {
    case 0:
        set ? STATUS(Q3MatrixTransform_Set(transform, nullArg ? nullptr : &matrix))
            : STATUS(Q3MatrixTransform_Get(transform, nullArg ? nullptr : &matrix));
        break;
    case 1:
        set ? STATUS(Q3TranslateTransform_Set(transform, nullArg ? nullptr : &vector))
            : STATUS(Q3TranslateTransform_Get(transform, nullArg ? nullptr : &vector));
        break;
    case 2:
        set ? STATUS(Q3ScaleTransform_Set(transform, nullArg ? nullptr : &vector))
            : STATUS(Q3ScaleTransform_Get(transform, nullArg ? nullptr : &vector));
        break;
    case 3:
        set ? STATUS(Q3RotateTransform_SetData(transform, nullArg ? nullptr : &rotate))
            : STATUS(Q3RotateTransform_GetData(transform, nullArg ? nullptr : &rotate));
        break;
    case 4:
        set ? STATUS(q3fuzz_RotateTransform_SetAxis(transform, rawAxis))
            : STATUS(Q3RotateTransform_GetAxis(transform, nullArg ? nullptr : &axisOut));
        break;
    case 5:
        set ? STATUS(Q3RotateTransform_SetAngle(transform, radians))
            : STATUS(Q3RotateTransform_GetAngle(transform, nullArg ? nullptr : &radians));
        break;
    default:
        if (set)
            QUERY(Q3Transform_GetType(transform), TQ3ObjectType{kQ3ObjectTypeInvalid});
        else
            POINTER(Q3Transform_GetMatrix(transform, nullArg ? nullptr : &matrix));
        break;
    }
}

void Session::cameraField(bool set, bool nullArg)
{
    using Setter = TQ3Status (*)(TQ3CameraObject, float);
    using Getter = TQ3Status (*)(TQ3CameraObject, float*);
    struct Field {
        const char* name;
        Setter setter;
        Getter getter;
    };
    static const Field kFields[] = {
        {"Q3OrthographicCamera_Left", Q3OrthographicCamera_SetLeft, Q3OrthographicCamera_GetLeft},
        {"Q3OrthographicCamera_Top", Q3OrthographicCamera_SetTop, Q3OrthographicCamera_GetTop},
        {"Q3OrthographicCamera_Right", Q3OrthographicCamera_SetRight, Q3OrthographicCamera_GetRight},
        {"Q3OrthographicCamera_Bottom", Q3OrthographicCamera_SetBottom, Q3OrthographicCamera_GetBottom},
        {"Q3ViewPlaneCamera_ViewPlane", Q3ViewPlaneCamera_SetViewPlane, Q3ViewPlaneCamera_GetViewPlane},
        {"Q3ViewPlaneCamera_HalfWidth", Q3ViewPlaneCamera_SetHalfWidth, Q3ViewPlaneCamera_GetHalfWidth},
        {"Q3ViewPlaneCamera_HalfHeight", Q3ViewPlaneCamera_SetHalfHeight, Q3ViewPlaneCamera_GetHalfHeight},
        {"Q3ViewPlaneCamera_CenterX", Q3ViewPlaneCamera_SetCenterX, Q3ViewPlaneCamera_GetCenterX},
        {"Q3ViewPlaneCamera_CenterY", Q3ViewPlaneCamera_SetCenterY, Q3ViewPlaneCamera_GetCenterY},
        {"Q3ViewAngleAspectCamera_FOV", Q3ViewAngleAspectCamera_SetFOV, Q3ViewAngleAspectCamera_GetFOV},
        {"Q3ViewAngleAspectCamera_AspectRatio", Q3ViewAngleAspectCamera_SetAspectRatio,
         Q3ViewAngleAspectCamera_GetAspectRatio},
    };
    const Field& field = kFields[m_in.u8() % (sizeof kFields / sizeof kFields[0])];
    const TQ3Object camera = pick(Kind::kCamera);
    float value = m_in.value();
    begin();
    const TQ3Status status = set ? field.setter(camera, value) : field.getter(camera, nullArg ? nullptr : &value);
    checkStatus(field.name, status);
}

// Action 0 GetData and EmptyData twice, 1 SetData (checked as
// surfaceAction checks it), 2 EmptyData(NULL); the data from the
// description, read whatever the action.
void Session::otherGeometryEdit()
{
    const std::uint8_t family = m_in.u8() % 3;
    const std::uint8_t action = m_in.u8() % 3;
    const bool nullData = m_in.u8() == 0;
    // The first three surfaceAction actions, in this operation's order.
    const std::uint8_t shared = action == 0 ? 2 : 1;
    DataArena arena;
    if (family == 0) {
        TQ3PointData data{};
        readDescribed(data, arena);
        if (action == 2)
            STATUS(Q3Point_EmptyData(nullptr));
        else
            surfaceAction<TQ3PointData>(shared, Kind::kPoint, nullData ? nullptr : &data, Q3Point_New,
                                        Q3Point_SetData, Q3Point_GetData, Q3Point_EmptyData, Q3Point_Submit,
                                        [](const TQ3PointData& a, const TQ3PointData& b) { return sameData(a, b); });
    } else if (family == 1) {
        TQ3LineData data{};
        readDescribed(data, arena);
        if (action == 2)
            STATUS(Q3Line_EmptyData(nullptr));
        else
            surfaceAction<TQ3LineData>(shared, Kind::kLine, nullData ? nullptr : &data, Q3Line_New, Q3Line_SetData,
                                       Q3Line_GetData, Q3Line_EmptyData, Q3Line_Submit,
                                       [](const TQ3LineData& a, const TQ3LineData& b) { return sameData(a, b); });
    } else {
        TQ3PolyLineData data{};
        readDescribed(data, arena);
        if (action == 2)
            STATUS(Q3PolyLine_EmptyData(nullptr));
        else if (action == 0 || drawAllowed())
            surfaceAction<TQ3PolyLineData>(
                shared, Kind::kPolyLine, nullData ? nullptr : &data, Q3PolyLine_New, Q3PolyLine_SetData,
                Q3PolyLine_GetData, Q3PolyLine_EmptyData, Q3PolyLine_Submit,
                [](const TQ3PolyLineData& a, const TQ3PolyLineData& b) { return sameData(a, b); });
    }
}

void Session::surfaces()
{
    const std::uint8_t family = m_in.u8() % 3;
    const std::uint8_t action = m_in.u8() % 5;
    const Kind kind = family == 0 ? Kind::kTriangle : family == 1 ? Kind::kPolygon : Kind::kTriMesh;
    DataArena arena;
    if (family == 0) {
        const bool nullData = m_in.u8() == 0;
        TQ3TriangleData data{};
        const TQ3AttributeSet set = readDescribed(data, arena);
        surfaceAction<TQ3TriangleData>(action, kind, nullData ? nullptr : &data, Q3Triangle_New, Q3Triangle_SetData,
                                       Q3Triangle_GetData, Q3Triangle_EmptyData, Q3Triangle_Submit,
                                       [](const TQ3TriangleData& a, const TQ3TriangleData& b) { return sameData(a, b); });
        if (action == 4)
            vertexCalls(kind, 3, set, Q3Triangle_GetVertexPosition, Q3Triangle_SetVertexPosition,
                        Q3Triangle_GetVertexAttributeSet, Q3Triangle_SetVertexAttributeSet);
    } else if (family == 1) {
        const bool nullData = m_in.u8() == 0;
        TQ3PolygonData data{};
        const TQ3AttributeSet set = readDescribed(data, arena);
        surfaceAction<TQ3PolygonData>(action, kind, nullData ? nullptr : &data, Q3Polygon_New, Q3Polygon_SetData,
                                      Q3Polygon_GetData, Q3Polygon_EmptyData, Q3Polygon_Submit,
                                      [](const TQ3PolygonData& a, const TQ3PolygonData& b) { return sameData(a, b); });
        if (action == 4)
            vertexCalls(kind, 12, set, Q3Polygon_GetVertexPosition, Q3Polygon_SetVertexPosition,
                        Q3Polygon_GetVertexAttributeSet, Q3Polygon_SetVertexAttributeSet);
    } else {
        // TriMeshes keep a hand-written generator here (described() has the
        // one from the description): the indices a description cannot
        // state (each below numPoints or numTriangles) are what reach the
        // renderer.
        const TQ3AttributeSet set = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        const bool nullData = m_in.u8() == 0;
        TriMeshBuffers mesh;
        readTriMesh(mesh, set);
        surfaceAction<TQ3TriMeshData>(action, kind, nullData ? nullptr : &mesh.data, Q3TriMesh_New,
                                      Q3TriMesh_SetData, Q3TriMesh_GetData, Q3TriMesh_EmptyData,
                                      Q3TriMesh_Submit, [&](const TQ3TriMeshData& a, const TQ3TriMeshData& b) {
                                          return a.numPoints == b.numPoints && a.numTriangles == b.numTriangles &&
                                                 (a.numPoints == 0 ||
                                                  std::memcmp(a.points, b.points,
                                                              a.numPoints * sizeof(TQ3Point3D)) == 0) &&
                                                 a.triMeshAttributeSet == b.triMeshAttributeSet;
                                      });
    }
}

void Session::readTriMesh(TriMeshBuffers& m, TQ3AttributeSet set)
{
    m.points.resize(m_in.u8() % 10);
    for (TQ3Point3D& p : m.points)
        p = point3();
    const unsigned long points = m.points.size();
    m.triangles.resize(m_in.u8() % 10);
    for (TQ3TriMeshTriangleData& t : m.triangles)
        for (unsigned long& i : t.pointIndices)
            i = m_in.index(points);
    m.edges.resize(m_in.u8() % 4);
    for (TQ3TriMeshEdgeData& e : m.edges) {
        e.pointIndices[0] = m_in.index(points);
        e.pointIndices[1] = m_in.index(points);
        e.triangleIndices[0] = (m_in.u8() & 1) ? (unsigned long)kQ3ArrayIndexNULL : m_in.index(m.triangles.size());
        e.triangleIndices[1] = 0xFFFFFFFFUL;
    }
    // Attribute arrays per vertex and per triangle: the standard types
    // (1..10) and some that are not; values with NaN and Inf possible.
    for (int a = m_in.u8() % 3; a > 0; --a) {
        const bool onVertices = m_in.u8() & 1;
        const std::size_t count = onVertices ? points : m.triangles.size();
        const std::uint8_t raw = m_in.u8();
        const TQ3AttributeType type = raw < 200 ? 1 + raw % 10 : TQ3AttributeType(std::int8_t(raw));
        m.values.emplace_back(count * 6 + 1);
        for (float& v : m.values.back())
            v = (m_in.u8() % 8 == 0) ? m_in.value() : float(m_in.u8() % 2);
        m.uses.emplace_back();
        if (m_in.u8() & 1) {
            m.uses.back().resize(count + 1);
            for (char& u : m.uses.back())
                u = char(m_in.u8() & 1);
        }
        (onVertices ? m.vertexAttributes : m.triangleAttributes)
            .push_back(TQ3TriMeshAttributeData{type, m.values.back().data(),
                                               m.uses.back().empty() ? nullptr : m.uses.back().data()});
    }
    TQ3TriMeshData& d = m.data;
    d.triMeshAttributeSet = set;
    d.numTriangles = m.triangles.size();
    d.triangles = m.triangles.empty() ? nullptr : m.triangles.data();
    d.numEdges = m.edges.size();
    d.edges = m.edges.empty() ? nullptr : m.edges.data();
    d.numPoints = points;
    d.points = m.points.empty() ? nullptr : m.points.data();
    d.numVertexAttributeTypes = m.vertexAttributes.size();
    d.vertexAttributeTypes = m.vertexAttributes.empty() ? nullptr : m.vertexAttributes.data();
    d.numTriangleAttributeTypes = m.triangleAttributes.size();
    d.triangleAttributeTypes = m.triangleAttributes.empty() ? nullptr : m.triangleAttributes.data();
    if (m_in.u8() == 0) {
        d.numTriangles = ~0UL - m_in.u8();
        d.triangles = nullptr;
    }
}

void Session::vertexCalls(Kind kind, unsigned long count, TQ3AttributeSet set,
                 TQ3Status (*getPosition)(TQ3GeometryObject, unsigned long, TQ3Point3D*),
                 TQ3Status (*setPosition)(TQ3GeometryObject, unsigned long, const TQ3Point3D*),
                 TQ3Status (*getSet)(TQ3GeometryObject, unsigned long, TQ3AttributeSet*),
                 TQ3Status (*setSet)(TQ3GeometryObject, unsigned long, TQ3AttributeSet))
{
    const TQ3Object geometry = pick(kind);
    const unsigned long index = m_in.index(count);
    const bool nullArg = m_in.u8() == 0;
    TQ3Point3D position = point3();
    TQ3AttributeSet got = nullptr;
    switch (m_in.u8() % 4) {
    case 0: STATUS(getPosition(geometry, index, nullArg ? nullptr : &position)); break;
    case 1: STATUS(setPosition(geometry, index, nullArg ? nullptr : &position)); break;
    case 2: STATUS(getSet(geometry, index, nullArg ? nullptr : &got)); break;
    default: STATUS(setSet(geometry, index, set)); break;
    }
    if (got != nullptr)
        hold(got, Kind::kAttributeSet);
}

void Session::quadrics()
{
    const std::uint8_t type = m_in.u8() % 7;
    const std::uint8_t action = m_in.u8() % 6;
    const Kind kind = Kind(int(Kind::kBox) + type);
    const bool nullData = m_in.u8() == 0;
    if (action == 4)
        return quadricField(type, kind);
    if (action == 5)
        return quadricDecompose(kind);
    switch (type) {
    case 0:
        quadricData(action, kind, nullData, Q3Box_New, Q3Box_SetData, Q3Box_GetData, Q3Box_EmptyData, Q3Box_Submit);
        break;
    case 1:
        quadricData(action, kind, nullData, Q3Cone_New, Q3Cone_SetData, Q3Cone_GetData, Q3Cone_EmptyData,
                    Q3Cone_Submit);
        break;
    case 2:
        quadricData(action, kind, nullData, Q3Cylinder_New, Q3Cylinder_SetData, Q3Cylinder_GetData,
                    Q3Cylinder_EmptyData, Q3Cylinder_Submit);
        break;
    case 3:
        quadricData(action, kind, nullData, Q3Disk_New, Q3Disk_SetData, Q3Disk_GetData, Q3Disk_EmptyData,
                    Q3Disk_Submit);
        break;
    case 4:
        quadricData(action, kind, nullData, Q3Ellipse_New, Q3Ellipse_SetData, Q3Ellipse_GetData,
                    Q3Ellipse_EmptyData, Q3Ellipse_Submit);
        break;
    case 5:
        quadricData(action, kind, nullData, Q3Ellipsoid_New, Q3Ellipsoid_SetData, Q3Ellipsoid_GetData,
                    Q3Ellipsoid_EmptyData, Q3Ellipsoid_Submit);
        break;
    default:
        quadricData(action, kind, nullData, Q3Torus_New, Q3Torus_SetData, Q3Torus_GetData, Q3Torus_EmptyData,
                    Q3Torus_Submit);
        break;
    }
}

void Session::described()
{
    const std::uint8_t type = m_in.u8() % 8;
    const std::uint8_t action = m_in.u8() % 4;
    const bool nullData = m_in.u8() == 0;
    switch (type) {
    case 0:
        describedAction(action, Kind::kGeneralPolygon, nullData, Q3GeneralPolygon_New, Q3GeneralPolygon_SetData,
                        Q3GeneralPolygon_GetData, Q3GeneralPolygon_EmptyData, Q3GeneralPolygon_Submit);
        break;
    case 1:
        describedAction(action, Kind::kMarker, nullData, Q3Marker_New, Q3Marker_SetData, Q3Marker_GetData,
                        Q3Marker_EmptyData, Q3Marker_Submit);
        break;
    case 2:
        describedAction(action, Kind::kPixmapMarker, nullData, Q3PixmapMarker_New, Q3PixmapMarker_SetData,
                        Q3PixmapMarker_GetData, Q3PixmapMarker_EmptyData, Q3PixmapMarker_Submit);
        break;
    case 3:
        describedAction(action, Kind::kCurve, nullData, Q3NURBCurve_New, Q3NURBCurve_SetData, Q3NURBCurve_GetData,
                        Q3NURBCurve_EmptyData, Q3NURBCurve_Submit);
        refreshCurveShapes();
        break;
    case 4:
        describedAction(action, Kind::kPatch, nullData, Q3NURBPatch_New, Q3NURBPatch_SetData, Q3NURBPatch_GetData,
                        Q3NURBPatch_EmptyData, Q3NURBPatch_Submit);
        break;
    case 5:
        describedAction(action, Kind::kPolyhedron, nullData, Q3Polyhedron_New, Q3Polyhedron_SetData,
                        Q3Polyhedron_GetData, Q3Polyhedron_EmptyData, Q3Polyhedron_Submit);
        break;
    case 6:
        describedAction(action, Kind::kTriGrid, nullData, Q3TriGrid_New, Q3TriGrid_SetData, Q3TriGrid_GetData,
                        Q3TriGrid_EmptyData, Q3TriGrid_Submit);
        break;
    default:
        // Q3 computes bBox from the points (QD3DGeometry.h), whatever the
        // caller gave.
        describedAction(action, Kind::kTriMesh, nullData, Q3TriMesh_New, Q3TriMesh_SetData, Q3TriMesh_GetData,
                        Q3TriMesh_EmptyData, Q3TriMesh_Submit, [](const TQ3TriMeshData& got, const TQ3TriMeshData& set) {
                            TQ3TriMeshData expected = set;
                            expected.bBox = got.bBox;
                            return sameData(got, expected);
                        });
        break;
    }
}

void Session::refreshCurveShapes()
{
    for (const Held& h : m_held) {
        if (h.kind != Kind::kCurve || m_initialized == 0)
            continue;
        TQ3NURBCurveData data{};
        if (STATUS(Q3NURBCurve_GetData(h.handle, &data)) != kQ3Success)
            continue;
        m_curves[h.handle] = CurveShape{data.order, data.numPoints};
        STATUS(Q3NURBCurve_EmptyData(&data));
    }
}

void Session::polygons2()
{
    const std::uint8_t type = m_in.u8() % 4;
    const std::uint8_t action = m_in.u8() % 5;
    const Kind kind = Kind(int(Kind::kGeneralPolygon) + type);
    const bool nullData = m_in.u8() == 0;
    if (action == 4)
        return polygons2Field(type, kind);
    if (action == 3 && !drawAllowed())
        return;
    std::vector<TQ3Vertex3D> vertices(2 + m_in.u8() % 10);
    for (TQ3Vertex3D& v : vertices) {
        v.point = TQ3Point3D{float(m_in.u8() % 7), float(m_in.u8() % 7), 0.0f};
        v.attributeSet = (m_in.u8() % 8 == 0) ? pick(Kind::kAttributeSet) : nullptr;
    }
    for (int n = m_in.u8() % 3; n > 0; --n)
        vertices[m_in.u8() % vertices.size()].point.z = m_in.value();
    const unsigned long count = static_cast<unsigned long>(vertices.size());
    // Now and then a count no array could hold, which must be refused
    // before any array is read (a smaller lie would make the fuzzer, not
    // Q3, read past its own arrays).
    const bool rawCount = m_in.u8() % 16 == 0;
    const unsigned long hugeCount =
        !rawCount ? 0 : m_in.u8() % 2 ? ~0UL : static_cast<unsigned long>(kQ3GeometryMaxArrayCount) + 1 + m_in.u8();
    switch (type) {
    case 0: {
        std::vector<TQ3GeneralPolygonContourData> contours;
        for (unsigned long first = 0; first < count;) {
            const unsigned long n = std::min<unsigned long>(count - first, 1 + m_in.u8() % 6);
            contours.push_back({n, vertices.data() + first});
            first += n;
        }
        TQ3GeneralPolygonData data{static_cast<unsigned long>(contours.size()), contours.data(),
                                   kQ3GeneralPolygonShapeHintComplex, nullptr};
        setRaw(data.shapeHint, enumValue(3));
        if (rawCount)
            data.numContours = hugeCount;
        surfaceAction<TQ3GeneralPolygonData>(
            action, kind, nullData ? nullptr : &data, Q3GeneralPolygon_New, Q3GeneralPolygon_SetData,
            Q3GeneralPolygon_GetData, Q3GeneralPolygon_EmptyData, Q3GeneralPolygon_Submit,
            [](const TQ3GeneralPolygonData& a, const TQ3GeneralPolygonData& b) {
                if (a.numContours != b.numContours || a.shapeHint != b.shapeHint)
                    return false;
                for (unsigned long c = 0; c < a.numContours; ++c)
                    if (a.contours[c].numVertices != b.contours[c].numVertices ||
                        !samePoints(a.contours[c].vertices, b.contours[c].vertices, a.contours[c].numVertices))
                        return false;
                return true;
            });
        break;
    }
    case 1: {
        std::vector<TQ3PolyhedronTriangleData> triangles(1 + m_in.u8() % 6);
        for (TQ3PolyhedronTriangleData& t : triangles) {
            for (unsigned long& index : t.vertexIndices)
                index = m_in.u8() % 32 == 0 ? m_in.u32() : m_in.index(count);
            t.edgeFlag = m_in.u8() % 9;
            t.triangleAttributeSet = (m_in.u8() % 4 == 0) ? pick(Kind::kAttributeSet) : nullptr;
        }
        std::vector<TQ3PolyhedronEdgeData> edges(m_in.u8() % 4);
        for (TQ3PolyhedronEdgeData& e : edges) {
            e.vertexIndices[0] = m_in.index(count + 1);
            e.vertexIndices[1] = m_in.index(count);
            e.triangleIndices[0] = m_in.index(triangles.size() + 1);
            e.triangleIndices[1] = m_in.u8() % 2 ? ~0UL : m_in.index(triangles.size());
            e.edgeAttributeSet = (m_in.u8() % 4 == 0) ? pick(Kind::kAttributeSet) : nullptr;
        }
        TQ3PolyhedronData data{count, vertices.data(), static_cast<unsigned long>(edges.size()),
                               edges.empty() ? nullptr : edges.data(),
                               static_cast<unsigned long>(triangles.size()), triangles.data(), nullptr};
        if (rawCount)
            data.numTriangles = hugeCount;
        surfaceAction<TQ3PolyhedronData>(
            action, kind, nullData ? nullptr : &data, Q3Polyhedron_New, Q3Polyhedron_SetData,
            Q3Polyhedron_GetData, Q3Polyhedron_EmptyData, Q3Polyhedron_Submit,
            [](const TQ3PolyhedronData& a, const TQ3PolyhedronData& b) {
                return a.numVertices == b.numVertices && a.numEdges == b.numEdges &&
                       a.numTriangles == b.numTriangles && samePoints(a.vertices, b.vertices, a.numVertices);
            });
        break;
    }
    case 2: {
        const unsigned long columns = 1 + m_in.u8() % 4;
        const unsigned long rows = count / columns;
        std::vector<TQ3AttributeSet> facets(2 * count, nullptr);
        for (TQ3AttributeSet& f : facets)
            f = (m_in.u8() % 8 == 0) ? pick(Kind::kAttributeSet) : nullptr;
        TQ3TriGridData data{rows, columns, vertices.data(), (m_in.u8() & 1) ? facets.data() : nullptr, nullptr};
        if (rawCount)
            data.numRows = hugeCount;
        surfaceAction<TQ3TriGridData>(action, kind, nullData ? nullptr : &data, Q3TriGrid_New, Q3TriGrid_SetData,
                                      Q3TriGrid_GetData, Q3TriGrid_EmptyData, Q3TriGrid_Submit,
                                      [](const TQ3TriGridData& a, const TQ3TriGridData& b) {
                                          return a.numRows == b.numRows && a.numColumns == b.numColumns &&
                                                 samePoints(a.vertices, b.vertices, a.numRows * a.numColumns);
                                      });
        break;
    }
    default: {
        std::vector<unsigned char> bits(1 + m_in.u8() % 16);
        for (unsigned char& b : bits)
            b = m_in.u8();
        TQ3MarkerData data{};
        data.location = TQ3Point3D{vertices[0].point.z, 0.0f, 0.0f};
        data.xOffset = static_cast<long>(static_cast<std::int32_t>(m_in.u32()));
        data.yOffset = static_cast<long>(static_cast<std::int8_t>(m_in.u8()));
        data.bitmap.image = bits.data();
        data.bitmap.rowBytes = 1 + m_in.u8() % 2;
        data.bitmap.height = bits.size() / data.bitmap.rowBytes;
        data.bitmap.width = m_in.u8() % 20;
        setRaw(data.bitmap.bitOrder, enumValue(2));
        if (rawCount)
            data.bitmap.height = hugeCount;
        surfaceAction<TQ3MarkerData>(action, kind, nullData ? nullptr : &data, Q3Marker_New, Q3Marker_SetData,
                                     Q3Marker_GetData, Q3Marker_EmptyData, Q3Marker_Submit,
                                     [](const TQ3MarkerData& a, const TQ3MarkerData& b) {
                                         return sameBytes(a.location, b.location) && a.xOffset == b.xOffset &&
                                                a.yOffset == b.yOffset && a.bitmap.width == b.bitmap.width &&
                                                a.bitmap.height == b.bitmap.height &&
                                                std::memcmp(a.bitmap.image, b.bitmap.image,
                                                            a.bitmap.rowBytes * a.bitmap.height) == 0;
                                     });
        break;
    }
    }
}

void Session::polygons2Field(std::uint8_t type, Kind kind)
{
    const TQ3Object geometry = pick(kind);
    const bool ours = holdsKind(geometry, kind) && m_initialized > 0;
    const bool nullArg = m_in.u8() == 0;
    const std::uint8_t call = m_in.u8();
    const unsigned long i = m_in.u8() % 8 == 0 ? m_in.u32() : m_in.u8() % 8;
    const unsigned long j = m_in.u8() % 8 == 0 ? m_in.u32() : m_in.u8() % 8;
    const TQ3Point3D point = point3();
    const TQ3AttributeSet attributes = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
    const unsigned long before = ours ? editIndex(geometry) : 0;
    TQ3Point3D pointOut{};
    TQ3AttributeSet got = nullptr;
    TQ3Status status = kQ3Success;
    bool edit = false;
    switch (type) {
    case 0:
        switch (call % 6) {
        case 0: STATUS(Q3GeneralPolygon_GetVertexPosition(geometry, i, j, nullArg ? nullptr : &pointOut)); break;
        case 1:
            edit = true;
            status = STATUS(Q3GeneralPolygon_SetVertexPosition(geometry, i, j, nullArg ? nullptr : &point));
            break;
        case 2: STATUS(Q3GeneralPolygon_GetVertexAttributeSet(geometry, i, j, nullArg ? nullptr : &got)); break;
        case 3:
            edit = true;
            status = STATUS(Q3GeneralPolygon_SetVertexAttributeSet(geometry, i, j, attributes));
            break;
        case 4: {
            TQ3GeneralPolygonShapeHint hint{};
            STATUS(Q3GeneralPolygon_GetShapeHint(geometry, nullArg ? nullptr : &hint));
            break;
        }
        default: {
            // From C: a hint outside the enumeration cannot be passed from C++.
            const int hint = enumValue(3);
            edit = true;
            status = STATUS(q3fuzz_GeneralPolygon_SetShapeHint(geometry, hint));
            break;
        }
        }
        break;
    case 1:
        switch (call % 8) {
        case 0: STATUS(Q3Polyhedron_GetVertexPosition(geometry, i, nullArg ? nullptr : &pointOut)); break;
        case 1:
            edit = true;
            status = STATUS(Q3Polyhedron_SetVertexPosition(geometry, i, nullArg ? nullptr : &point));
            break;
        case 2: STATUS(Q3Polyhedron_GetVertexAttributeSet(geometry, i, nullArg ? nullptr : &got)); break;
        case 3:
            edit = true;
            status = STATUS(Q3Polyhedron_SetVertexAttributeSet(geometry, i, attributes));
            break;
        case 4: {
            TQ3PolyhedronTriangleData t{};
            if (STATUS(Q3Polyhedron_GetTriangleData(geometry, i, nullArg ? nullptr : &t)) == kQ3Success)
                got = t.triangleAttributeSet;
            break;
        }
        case 5: {
            const TQ3PolyhedronTriangleData t{{j, j % 4, i % 4}, j % 9, attributes};
            edit = true;
            status = STATUS(Q3Polyhedron_SetTriangleData(geometry, i, nullArg ? nullptr : &t));
            break;
        }
        case 6: {
            TQ3PolyhedronEdgeData e{};
            if (STATUS(Q3Polyhedron_GetEdgeData(geometry, i, nullArg ? nullptr : &e)) == kQ3Success)
                got = e.edgeAttributeSet;
            break;
        }
        default: {
            const TQ3PolyhedronEdgeData e{{j % 4, j}, {i % 2, ~0UL}, attributes};
            edit = true;
            status = STATUS(Q3Polyhedron_SetEdgeData(geometry, i, nullArg ? nullptr : &e));
            break;
        }
        }
        break;
    case 2:
        switch (call % 6) {
        case 0: STATUS(Q3TriGrid_GetVertexPosition(geometry, i, j, nullArg ? nullptr : &pointOut)); break;
        case 1:
            edit = true;
            status = STATUS(Q3TriGrid_SetVertexPosition(geometry, i, j, nullArg ? nullptr : &point));
            break;
        case 2: STATUS(Q3TriGrid_GetVertexAttributeSet(geometry, i, j, nullArg ? nullptr : &got)); break;
        case 3:
            edit = true;
            status = STATUS(Q3TriGrid_SetVertexAttributeSet(geometry, i, j, attributes));
            break;
        case 4: STATUS(Q3TriGrid_GetFacetAttributeSet(geometry, i, nullArg ? nullptr : &got)); break;
        default:
            edit = true;
            status = STATUS(Q3TriGrid_SetFacetAttributeSet(geometry, i, attributes));
            break;
        }
        break;
    default:
        switch (call % 8) {
        case 0: STATUS(Q3Marker_GetPosition(geometry, nullArg ? nullptr : &pointOut)); break;
        case 1:
            edit = true;
            status = STATUS(Q3Marker_SetPosition(geometry, nullArg ? nullptr : &point));
            break;
        case 2: {
            long offset = 0;
            STATUS(Q3Marker_GetXOffset(geometry, nullArg ? nullptr : &offset));
            STATUS(Q3Marker_GetYOffset(geometry, nullArg ? nullptr : &offset));
            break;
        }
        case 3:
            edit = true;
            status = STATUS(Q3Marker_SetXOffset(geometry, static_cast<long>(j)));
            break;
        case 4:
            edit = true;
            status = STATUS(Q3Marker_SetYOffset(geometry, -static_cast<long>(i)));
            break;
        case 5: {
            TQ3Bitmap bitmap{};
            if (STATUS(Q3Marker_GetBitmap(geometry, nullArg ? nullptr : &bitmap)) == kQ3Success)
                STATUS(Q3Bitmap_Empty(&bitmap));
            break;
        }
        case 6: {
            unsigned char bits[8] = {static_cast<unsigned char>(i), static_cast<unsigned char>(j), 0xFF, 0x81, 0x18};
            TQ3Bitmap bitmap{bits, j % 20, 1 + i % 4, 1 + i % 2, kQ3EndianBig};
            setRaw(bitmap.bitOrder, std::int32_t(j % 3));
            edit = true;
            status = STATUS(Q3Marker_SetBitmap(geometry, nullArg ? nullptr : &bitmap));
            break;
        }
        default:
            QUERY(Q3Bitmap_GetImageSize(i, j), 0UL);
            break;
        }
        break;
    }
    if (edit && ours && status != kQ3Success)
        require(editIndex(geometry) == before, "polygons2", "a failed edit changed the edit index");
    if (edit)
        require(status == kQ3Failure || ours, "polygons2", "an edit succeeded on something not held");
    if (got != nullptr)
        hold(got, Kind::kAttributeSet);
}

Session::StoragePixmapArgs Session::storagePixmap()
{
    StoragePixmapArgs a;
    const std::uint8_t flags = m_in.u8();
    const std::int32_t type = enumValue(6);
    const unsigned long bits = type == 5 ? 24 : (type >= 2 && type <= 4) ? 16 : 32;
    const unsigned long width = (flags & 1) ? m_in.u32() : m_in.u8() % 9;
    const unsigned long height = (flags & 2) ? m_in.u32() : m_in.u8() % 9;
    a.pixmap.width = width;
    a.pixmap.height = height;
    a.pixmap.rowBytes = (flags & 4) ? m_in.u32() : width * (bits / 8) + m_in.u8() % 4;
    a.pixmap.pixelSize = (flags & 8) ? m_in.u8() : bits;
    setRaw(a.pixmap.pixelType, type);
    setRaw(a.pixmap.byteOrder, enumValue(2));
    setRaw(a.pixmap.bitOrder, enumValue(2));
    switch ((flags >> 4) & 3) {
    case 0: {
        // As many bytes as the pixmap needs (at most 4096), one fewer
        // when flag 0x40 says so; the first 16 from the input.
        const unsigned long long need =
            std::min<unsigned long long>((unsigned long long)a.pixmap.rowBytes * height, 4096ULL);
        std::vector<unsigned char> bytes(need);
        for (std::size_t i = 0; i < bytes.size(); ++i)
            bytes[i] = i < 16 ? m_in.u8() : static_cast<unsigned char>(i * 37);
        const unsigned long size = static_cast<unsigned long>(bytes.size()) - ((flags & 0x40) && need > 0 ? 1 : 0);
        a.made = OBJECT(Q3MemoryStorage_New(bytes.empty() ? nullptr : bytes.data(), size));
        a.pixmap.image = a.made;
        break;
    }
    case 1: a.pixmap.image = pick(Kind::kAttributeSet); break;
    case 2: a.pixmap.image = nullptr; break;
    default: a.pixmap.image = pick(Kind::kPixmapMarker); break;
    }
    return a;
}

void Session::releaseStorage(StoragePixmapArgs& a)
{
    if (a.made != nullptr)
        STATUS(Q3Object_Dispose(a.made));
    a.made = nullptr;
}

void Session::pixmapMarkers()
{
    const std::uint8_t action = m_in.u8() % 5;
    const bool nullData = m_in.u8() == 0;
    if (action == 4)
        return pixmapMarkerField();
    if (action == 3 && !drawAllowed())
        return;
    StoragePixmapArgs args = storagePixmap();
    TQ3PixmapMarkerData data{};
    data.position = point3();
    data.xOffset = static_cast<long>(static_cast<std::int32_t>(m_in.u32()));
    data.yOffset = static_cast<long>(static_cast<std::int8_t>(m_in.u8()));
    data.pixmap = args.pixmap;
    data.pixmapMarkerAttributeSet = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
    surfaceAction<TQ3PixmapMarkerData>(action, Kind::kPixmapMarker, nullData ? nullptr : &data,
                                       Q3PixmapMarker_New, Q3PixmapMarker_SetData, Q3PixmapMarker_GetData,
                                       Q3PixmapMarker_EmptyData, Q3PixmapMarker_Submit,
                                       [](const TQ3PixmapMarkerData& a, const TQ3PixmapMarkerData& b) {
                                           return sameBytes(a.position, b.position) && a.xOffset == b.xOffset &&
                                                  a.yOffset == b.yOffset && samePixmap(a.pixmap, b.pixmap) &&
                                                  a.pixmapMarkerAttributeSet == b.pixmapMarkerAttributeSet;
                                       });
    texturesFrom(args);
    releaseStorage(args);
}

void Session::texturesFrom(const StoragePixmapArgs& args)
{
    const TQ3StoragePixmap& p = args.pixmap;
    TQ3Mipmap mipmap{};
    mipmap.image = p.image;
    setRaw(mipmap.useMipmapping, static_cast<std::int32_t>(p.width & 1) == 0 ? 1 : 0);
    std::memcpy(&mipmap.pixelType, &p.pixelType, sizeof mipmap.pixelType);
    std::memcpy(&mipmap.bitOrder, &p.bitOrder, sizeof mipmap.bitOrder);
    std::memcpy(&mipmap.byteOrder, &p.byteOrder, sizeof mipmap.byteOrder);
    mipmap.mipmaps[0] = TQ3MipmapImage{p.width, p.height, p.rowBytes, 0};
    mipmap.mipmaps[1] = TQ3MipmapImage{p.width / 2, p.height / 2, p.rowBytes / 2, p.rowBytes * p.height};
    const TQ3Object textures[2] = {OBJECT(Q3PixmapTexture_New(&p)), OBJECT(Q3MipmapTexture_New(&mipmap))};
    for (TQ3Object texture : textures) {
        if (texture == nullptr)
            continue;
        unsigned long size = 0;
        STATUS(Q3Texture_GetWidth(texture, &size));
        STATUS(Q3Texture_GetHeight(texture, &size));
        if (Q3Texture_GetType(texture) == kQ3TextureTypePixmap) {
            TQ3StoragePixmap got{};
            if (STATUS(Q3PixmapTexture_GetPixmap(texture, &got)) == kQ3Success) {
                require(STATUS(Q3PixmapTexture_SetPixmap(texture, &got)) == kQ3Success,
                        "Q3PixmapTexture_SetPixmap", "refused what Q3PixmapTexture_GetPixmap gave");
                STATUS(Q3Object_Dispose(got.image));
            }
        } else {
            TQ3Mipmap got{};
            if (STATUS(Q3MipmapTexture_GetMipmap(texture, &got)) == kQ3Success) {
                require(STATUS(Q3MipmapTexture_SetMipmap(texture, &got)) == kQ3Success,
                        "Q3MipmapTexture_SetMipmap", "refused what Q3MipmapTexture_GetMipmap gave");
                STATUS(Q3Object_Dispose(got.image));
            }
        }
    }
    const TQ3Object shader = OBJECT(Q3TextureShader_New(textures[0] != nullptr ? textures[0] : textures[1]));
    if (shader != nullptr) {
        STATUS(Q3TextureShader_SetTexture(shader, textures[1] != nullptr ? textures[1] : textures[0]));
        TQ3TextureObject got = nullptr;
        if (STATUS(Q3TextureShader_GetTexture(shader, &got)) == kQ3Success)
            STATUS(Q3Object_Dispose(got));
        QUERY(Q3SurfaceShader_GetType(shader), kQ3ObjectTypeInvalid);
        STATUS(Q3Object_Dispose(shader));
    }
    for (TQ3Object texture : textures)
        if (texture != nullptr)
            STATUS(Q3Object_Dispose(texture));
    TQ3ColorRGB color{float(p.width), float(p.height), float(p.rowBytes)};
    float luminance = 0.0f;
    POINTER(Q3ColorRGB_Clamp(&color, &color));
    POINTER(Q3ColorRGB_Luminance(&color, &luminance));
}

void Session::pixmapMarkerField()
{
    const TQ3Object geometry = pick(Kind::kPixmapMarker);
    const bool ours = holdsKind(geometry, Kind::kPixmapMarker) && m_initialized > 0;
    const bool nullArg = m_in.u8() == 0;
    const std::uint8_t call = m_in.u8() % 8;
    const unsigned long before = ours ? editIndex(geometry) : 0;
    TQ3Status status = kQ3Success;
    bool edit = false;
    switch (call) {
    case 0: {
        TQ3Point3D p{};
        STATUS(Q3PixmapMarker_GetPosition(geometry, nullArg ? nullptr : &p));
        break;
    }
    case 1: {
        const TQ3Point3D p = point3();
        edit = true;
        status = STATUS(Q3PixmapMarker_SetPosition(geometry, nullArg ? nullptr : &p));
        break;
    }
    case 2: {
        long offset = 0;
        STATUS(Q3PixmapMarker_GetXOffset(geometry, nullArg ? nullptr : &offset));
        STATUS(Q3PixmapMarker_GetYOffset(geometry, nullArg ? nullptr : &offset));
        break;
    }
    case 3:
        edit = true;
        status = STATUS(Q3PixmapMarker_SetXOffset(geometry, static_cast<long>(static_cast<std::int32_t>(m_in.u32()))));
        break;
    case 4:
        edit = true;
        status = STATUS(Q3PixmapMarker_SetYOffset(geometry, (m_in.u8() & 1) ? LONG_MIN : LONG_MAX));
        break;
    case 5: {
        TQ3StoragePixmap pixmap;
        std::memset(&pixmap, 0xA5, sizeof pixmap);
        const TQ3StoragePixmap untouched = pixmap;
        if (STATUS(Q3PixmapMarker_GetPixmap(geometry, nullArg ? nullptr : &pixmap)) == kQ3Success) {
            require(Q3Object_IsType(pixmap.image, kQ3SharedTypeStorage) == kQ3True,
                    "Q3PixmapMarker_GetPixmap", "gave no storage");
            STATUS(Q3Object_Dispose(pixmap.image));
        } else {
            require(sameBytes(pixmap, untouched), "Q3PixmapMarker_GetPixmap", "failed but wrote its output");
        }
        break;
    }
    case 6: {
        StoragePixmapArgs args = storagePixmap();
        edit = true;
        status = STATUS(Q3PixmapMarker_SetPixmap(geometry, nullArg ? nullptr : &args.pixmap));
        if (status == kQ3Success) {
            TQ3StoragePixmap got{};
            STATUS(Q3PixmapMarker_GetPixmap(geometry, &got));
            require(samePixmap(got, args.pixmap), "Q3PixmapMarker_SetPixmap", "the pixmap read back differs");
            STATUS(Q3Object_Dispose(got.image));
        }
        releaseStorage(args);
        break;
    }
    default: {
        TQ3PixmapMarkerData got{};
        if (STATUS(Q3PixmapMarker_GetData(geometry, nullArg ? nullptr : &got)) == kQ3Success) {
            STATUS(Q3PixmapMarker_EmptyData(&got));
            require(got.pixmap.image == nullptr && got.pixmapMarkerAttributeSet == nullptr,
                    "Q3PixmapMarker_EmptyData", "left handles behind");
        }
        break;
    }
    }
    if (edit && ours && status != kQ3Success)
        require(editIndex(geometry) == before, "pixmapMarkers", "a failed edit changed the edit index");
    if (edit)
        require(status == kQ3Failure || ours, "pixmapMarkers", "an edit succeeded on something not held");
}

void Session::quadricField(std::uint8_t type, Kind kind)
{
    static const QuadricCalls kCalls[] = {
        {Q3Box_SetOrigin, Q3Box_GetOrigin, {Q3Box_SetOrientation, Q3Box_SetMajorAxis, Q3Box_SetMinorAxis},
         {Q3Box_GetOrientation, Q3Box_GetMajorAxis, Q3Box_GetMinorAxis}, {}, {}, nullptr, nullptr},
        {Q3Cone_SetOrigin, Q3Cone_GetOrigin, {Q3Cone_SetOrientation, Q3Cone_SetMajorRadius, Q3Cone_SetMinorRadius},
         {Q3Cone_GetOrientation, Q3Cone_GetMajorRadius, Q3Cone_GetMinorRadius},
         {Q3Cone_SetBottomAttributeSet, Q3Cone_SetFaceAttributeSet},
         {Q3Cone_GetBottomAttributeSet, Q3Cone_GetFaceAttributeSet}, Q3Cone_SetCaps, Q3Cone_GetCaps},
        {Q3Cylinder_SetOrigin, Q3Cylinder_GetOrigin,
         {Q3Cylinder_SetOrientation, Q3Cylinder_SetMajorRadius, Q3Cylinder_SetMinorRadius},
         {Q3Cylinder_GetOrientation, Q3Cylinder_GetMajorRadius, Q3Cylinder_GetMinorRadius},
         {Q3Cylinder_SetTopAttributeSet, Q3Cylinder_SetBottomAttributeSet, Q3Cylinder_SetFaceAttributeSet},
         {Q3Cylinder_GetTopAttributeSet, Q3Cylinder_GetBottomAttributeSet, Q3Cylinder_GetFaceAttributeSet},
         Q3Cylinder_SetCaps, Q3Cylinder_GetCaps},
        {Q3Disk_SetOrigin, Q3Disk_GetOrigin, {nullptr, Q3Disk_SetMajorRadius, Q3Disk_SetMinorRadius},
         {nullptr, Q3Disk_GetMajorRadius, Q3Disk_GetMinorRadius}, {}, {}, nullptr, nullptr},
        {Q3Ellipse_SetOrigin, Q3Ellipse_GetOrigin, {nullptr, Q3Ellipse_SetMajorRadius, Q3Ellipse_SetMinorRadius},
         {nullptr, Q3Ellipse_GetMajorRadius, Q3Ellipse_GetMinorRadius}, {}, {}, nullptr, nullptr},
        {Q3Ellipsoid_SetOrigin, Q3Ellipsoid_GetOrigin,
         {Q3Ellipsoid_SetOrientation, Q3Ellipsoid_SetMajorRadius, Q3Ellipsoid_SetMinorRadius},
         {Q3Ellipsoid_GetOrientation, Q3Ellipsoid_GetMajorRadius, Q3Ellipsoid_GetMinorRadius}, {}, {}, nullptr,
         nullptr},
        {Q3Torus_SetOrigin, Q3Torus_GetOrigin,
         {Q3Torus_SetOrientation, Q3Torus_SetMajorRadius, Q3Torus_SetMinorRadius},
         {Q3Torus_GetOrientation, Q3Torus_GetMajorRadius, Q3Torus_GetMinorRadius}, {}, {}, nullptr, nullptr},
    };
    const QuadricCalls& c = kCalls[type];
    const TQ3Object geometry = pick(kind);
    const bool ours = holdsKind(geometry, kind) && m_initialized > 0;
    const bool nullArg = m_in.u8() == 0;
    const bool set = m_in.u8() & 1;
    const std::uint8_t field = m_in.u8();
    const std::uint8_t slot = m_in.u8() % 3;
    const TQ3Point3D point = point3();
    const TQ3Vector3D vector{point.x, point.y, point.z};
    const float ratio = m_in.value();
    const TQ3EndCap caps = TQ3EndCap(enumValue(7));
    const TQ3AttributeSet attributes = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
    const unsigned long face = m_in.index(6);
    // A Set: a success reads back with its Get, a failure changes
    // neither the field nor the edit index.
    auto edit = [&](const char* name, auto get, auto wanted, auto call) {
        decltype(wanted) old{}, now{};
        const unsigned long before = ours ? editIndex(geometry) : 0;
        if (ours)
            STATUS(get(geometry, &old));
        const TQ3Status status = STATUS(call());
        require(status == kQ3Failure || ours, name, "succeeded on something that is not a held shape");
        if (!ours)
            return;
        STATUS(get(geometry, &now));
        if (status == kQ3Success)
            require(sameBytes(now, wanted), name, "does not read back");
        else
            require(sameBytes(now, old) && editIndex(geometry) == before, name, "failed but changed the shape");
    };
    TQ3Point3D pointOut{};
    TQ3Vector3D vectorOut{};
    TQ3AttributeSet got = nullptr;
    switch (field % 5) {
    case 0:
        if (set)
            edit("SetOrigin", c.getOrigin, point,
                 [&] { return c.setOrigin(geometry, nullArg ? nullptr : &point); });
        else
            STATUS(c.getOrigin(geometry, nullArg ? nullptr : &pointOut));
        break;
    case 1:
        if (c.setVector[slot] == nullptr)
            break;
        if (set)
            edit("SetVector", c.getVector[slot], vector,
                 [&] { return c.setVector[slot](geometry, nullArg ? nullptr : &vector); });
        else
            STATUS(c.getVector[slot](geometry, nullArg ? nullptr : &vectorOut));
        break;
    case 2:
        if (type == 0) {
            const unsigned long before = ours ? editIndex(geometry) : 0;
            if (!set)
                STATUS(Q3Box_GetFaceAttributeSet(geometry, face, nullArg ? nullptr : &got));
            else if (STATUS(Q3Box_SetFaceAttributeSet(geometry, face, attributes)) == kQ3Failure && ours)
                require(editIndex(geometry) == before, "Q3Box_SetFaceAttributeSet", "failed but changed the box");
        } else if (c.setSet[slot] != nullptr) {
            const unsigned long before = ours ? editIndex(geometry) : 0;
            if (!set)
                STATUS(c.getSet[slot](geometry, nullArg ? nullptr : &got));
            else if (STATUS(c.setSet[slot](geometry, attributes)) == kQ3Failure && ours)
                require(editIndex(geometry) == before, "SetAttributeSet", "failed but changed the shape");
        }
        break;
    case 3:
        if (type == 6) {
            float out = 0.0f;
            if (set)
                edit("Q3Torus_SetRatio", Q3Torus_GetRatio, ratio,
                     [&] { return Q3Torus_SetRatio(geometry, ratio); });
            else
                STATUS(Q3Torus_GetRatio(geometry, nullArg ? nullptr : &out));
        } else if (c.setCaps != nullptr) {
            TQ3EndCap out = 0;
            if (set)
                edit("SetCaps", c.getCaps, caps, [&] { return c.setCaps(geometry, caps); });
            else
                STATUS(c.getCaps(geometry, nullArg ? nullptr : &out));
        }
        break;
    default:
        QUERY(Q3Geometry_GetType(geometry), TQ3ObjectType{kQ3ObjectTypeInvalid});
        break;
    }
    if (got != nullptr)
        hold(got, Kind::kAttributeSet);
}

bool Session::meshCounts(TQ3Object mesh, MeshCounts& c)
{
    return STATUS(Q3Mesh_GetNumVertices(mesh, &c.vertices)) == kQ3Success &&
           STATUS(Q3Mesh_GetNumFaces(mesh, &c.faces)) == kQ3Success &&
           STATUS(Q3Mesh_GetNumEdges(mesh, &c.edges)) == kQ3Success &&
           STATUS(Q3Mesh_GetNumComponents(mesh, &c.components)) == kQ3Success &&
           STATUS(Q3Mesh_GetNumCorners(mesh, &c.corners)) == kQ3Success;
}

void* Session::meshPart()
{
    const std::uint8_t how = m_in.u8();
    if (how < 200 && !m_meshParts.empty())
        return m_meshParts[m_in.u8() % m_meshParts.size()];
    if (how < 220)
        return nullptr;
    return reinterpret_cast<void*>(static_cast<std::uintptr_t>(m_in.u32()));
}

void Session::rememberPart(void* part)
{
    if (part == nullptr)
        return;
    if (m_meshParts.size() < kMaxMeshParts)
        m_meshParts.push_back(part);
    else
        m_meshParts[m_in.u8() % kMaxMeshParts] = part;
}

void Session::meshes()
{
    const std::uint8_t action = m_in.u8() % 8;
    if (action == 0) {
        if (m_meshes < kMaxMeshes) {
            ++m_meshes;
            if (const TQ3Object mesh = OBJECT(Q3Mesh_New()))
                hold(mesh, Kind::kMesh);
        }
        return;
    }
    const TQ3Object mesh = pick(Kind::kMesh);
    const bool ours = holdsKind(mesh, Kind::kMesh) && m_initialized > 0;
    MeshCounts before;
    const bool counted = ours && meshCounts(mesh, before);
    const unsigned long edit = ours ? editIndex(mesh) : 0;
    bool failed = true;
    const char* call = "Q3Mesh edit";
    switch (action) {
    case 1: {
        call = "Q3Mesh_VertexNew";
        TQ3Vertex3D v{{m_in.value(), m_in.value(), m_in.value()}, nullptr};
        if (m_in.u8() & 1)
            v.attributeSet = pick(Kind::kAttributeSet);
        const bool vertexNull = m_in.u8() == 0;
        if (before.vertices >= kMaxMeshVertices)
            return;
        void* made = POINTER(Q3Mesh_VertexNew(mesh, vertexNull ? nullptr : &v));
        failed = made == nullptr;
        rememberPart(made);
        if (!failed) {
            before.vertices++;
            require(std::isfinite(v.point.x) && std::isfinite(v.point.y) && std::isfinite(v.point.z), call,
                    "accepted a point that is not finite");
        }
        break;
    }
    case 2: {
        call = "Q3Mesh_FaceNew";
        std::vector<TQ3MeshVertex> ring(3 + m_in.u8() % 6);
        const std::uint8_t source = m_in.u8();
        // Mostly the mesh's own vertices, walked; else remembered parts.
        std::vector<TQ3MeshVertex> own;
        if (ours) {
            TQ3MeshIterator it;
            for (TQ3MeshVertex v = QUERY(Q3Mesh_FirstMeshVertex(mesh, &it), TQ3MeshVertex(nullptr));
                 v != nullptr && own.size() < 64; v = QUERY(Q3Mesh_NextMeshVertex(&it), TQ3MeshVertex(nullptr)))
                own.push_back(v);
        }
        for (TQ3MeshVertex& v : ring)
            v = source < 200 && !own.empty() ? own[m_in.u8() % own.size()]
                                             : static_cast<TQ3MeshVertex>(meshPart());
        const unsigned long claimed = (m_in.u8() == 0) ? 2 : static_cast<unsigned long>(ring.size());
        TQ3AttributeSet set = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        void* made = POINTER(Q3Mesh_FaceNew(mesh, claimed, ring.data(), set));
        failed = made == nullptr;
        rememberPart(made);
        if (!failed) {
            // A ring that names a vertex twice is kept, as QuickDraw 3D
            // and Quesa keep it (docs/3dmf.md, "Tolerances"); fewer
            // than three vertices is refused.
            before.faces++;
            require(claimed >= 3, call, "accepted a bad vertex list");
        }
        break;
    }
    case 3: {
        void* part = meshPart();
        if (m_in.u8() & 1) {
            call = "Q3Mesh_VertexDelete";
            failed = STATUS(Q3Mesh_VertexDelete(mesh, static_cast<TQ3MeshVertex>(part))) == kQ3Failure;
        } else {
            call = "Q3Mesh_FaceDelete";
            failed = STATUS(Q3Mesh_FaceDelete(mesh, static_cast<TQ3MeshFace>(part))) == kQ3Failure;
            if (!failed)
                before.faces--;
        }
        break;
    }
    case 4: {
        void* a = meshPart();
        void* b = meshPart();
        void* made = nullptr;
        if (m_in.u8() & 1) {
            call = "Q3Mesh_FaceToContour";
            made = POINTER(Q3Mesh_FaceToContour(mesh, static_cast<TQ3MeshFace>(a), static_cast<TQ3MeshFace>(b)));
            if (made != nullptr) {
                require(a != b, call, "made a face a contour of itself");
                before.faces--;
            }
        } else {
            call = "Q3Mesh_ContourToFace";
            made = POINTER(Q3Mesh_ContourToFace(mesh, static_cast<TQ3MeshContour>(a)));
        }
        failed = made == nullptr;
        rememberPart(made);
        break;
    }
    case 5: {
        void* part = meshPart();
        TQ3AttributeSet set = (m_in.u8() & 1) ? pick(Kind::kAttributeSet) : nullptr;
        switch (m_in.u8() % 5) {
        case 0:
            call = "Q3Mesh_SetVertexAttributeSet";
            failed = STATUS(Q3Mesh_SetVertexAttributeSet(mesh, static_cast<TQ3MeshVertex>(part), set)) ==
                     kQ3Failure;
            break;
        case 1:
            call = "Q3Mesh_SetFaceAttributeSet";
            failed = STATUS(Q3Mesh_SetFaceAttributeSet(mesh, static_cast<TQ3MeshFace>(part), set)) == kQ3Failure;
            break;
        case 2:
            call = "Q3Mesh_SetEdgeAttributeSet";
            failed = STATUS(Q3Mesh_SetEdgeAttributeSet(mesh, static_cast<TQ3MeshEdge>(part), set)) == kQ3Failure;
            break;
        case 3: {
            call = "Q3Mesh_SetCornerAttributeSet";
            void* face = meshPart();
            failed = STATUS(Q3Mesh_SetCornerAttributeSet(mesh, static_cast<TQ3MeshVertex>(part),
                                                         static_cast<TQ3MeshFace>(face), set)) == kQ3Failure;
            break;
        }
        default: {
            call = "Q3Mesh_SetVertexCoordinates";
            const TQ3Point3D p{m_in.value(), m_in.value(), m_in.value()};
            failed = STATUS(Q3Mesh_SetVertexCoordinates(mesh, static_cast<TQ3MeshVertex>(part), &p)) ==
                     kQ3Failure;
            if (!failed)
                require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), call,
                        "accepted a point that is not finite");
        }
        }
        break;
    }
    case 6: {
        // A walk around a part, bounded: each Next obeys the contract.
        void* part = meshPart();
        TQ3MeshIterator it;
        void* h = nullptr;
        const std::uint8_t which = m_in.u8() % 13;
        switch (which) {
        case 0: h = QUERY(Q3Mesh_FirstComponentVertex(static_cast<TQ3MeshComponent>(part), &it), TQ3MeshVertex(nullptr)); break;
        case 1: h = QUERY(Q3Mesh_FirstComponentEdge(static_cast<TQ3MeshComponent>(part), &it), TQ3MeshEdge(nullptr)); break;
        case 2: h = QUERY(Q3Mesh_FirstVertexEdge(static_cast<TQ3MeshVertex>(part), &it), TQ3MeshEdge(nullptr)); break;
        case 3: h = QUERY(Q3Mesh_FirstVertexVertex(static_cast<TQ3MeshVertex>(part), &it), TQ3MeshVertex(nullptr)); break;
        case 4: h = QUERY(Q3Mesh_FirstVertexFace(static_cast<TQ3MeshVertex>(part), &it), TQ3MeshFace(nullptr)); break;
        case 5: h = QUERY(Q3Mesh_FirstFaceEdge(static_cast<TQ3MeshFace>(part), &it), TQ3MeshEdge(nullptr)); break;
        case 6: h = QUERY(Q3Mesh_FirstFaceVertex(static_cast<TQ3MeshFace>(part), &it), TQ3MeshVertex(nullptr)); break;
        case 7: h = QUERY(Q3Mesh_FirstFaceFace(static_cast<TQ3MeshFace>(part), &it), TQ3MeshFace(nullptr)); break;
        case 8: h = QUERY(Q3Mesh_FirstFaceContour(static_cast<TQ3MeshFace>(part), &it), TQ3MeshContour(nullptr)); break;
        case 9: h = QUERY(Q3Mesh_FirstContourEdge(static_cast<TQ3MeshContour>(part), &it), TQ3MeshEdge(nullptr)); break;
        case 10: h = QUERY(Q3Mesh_FirstContourVertex(static_cast<TQ3MeshContour>(part), &it), TQ3MeshVertex(nullptr)); break;
        case 11: h = QUERY(Q3Mesh_FirstContourFace(static_cast<TQ3MeshContour>(part), &it), TQ3MeshFace(nullptr)); break;
        default: h = QUERY(Q3Mesh_FirstMeshComponent(mesh, &it), TQ3MeshComponent(nullptr)); break;
        }
        for (int step = 0; h != nullptr && step < 4096; ++step) {
            rememberPart(h);
            switch (which) {
            case 0: h = QUERY(Q3Mesh_NextComponentVertex(&it), TQ3MeshVertex(nullptr)); break;
            case 1: h = QUERY(Q3Mesh_NextComponentEdge(&it), TQ3MeshEdge(nullptr)); break;
            case 2: h = QUERY(Q3Mesh_NextVertexEdge(&it), TQ3MeshEdge(nullptr)); break;
            case 3: h = QUERY(Q3Mesh_NextVertexVertex(&it), TQ3MeshVertex(nullptr)); break;
            case 4: h = QUERY(Q3Mesh_NextVertexFace(&it), TQ3MeshFace(nullptr)); break;
            case 5: h = QUERY(Q3Mesh_NextFaceEdge(&it), TQ3MeshEdge(nullptr)); break;
            case 6: h = QUERY(Q3Mesh_NextFaceVertex(&it), TQ3MeshVertex(nullptr)); break;
            case 7: h = QUERY(Q3Mesh_NextFaceFace(&it), TQ3MeshFace(nullptr)); break;
            case 8: h = QUERY(Q3Mesh_NextFaceContour(&it), TQ3MeshContour(nullptr)); break;
            case 9: h = QUERY(Q3Mesh_NextContourEdge(&it), TQ3MeshEdge(nullptr)); break;
            case 10: h = QUERY(Q3Mesh_NextContourVertex(&it), TQ3MeshVertex(nullptr)); break;
            case 11: h = QUERY(Q3Mesh_NextContourFace(&it), TQ3MeshFace(nullptr)); break;
            default: h = QUERY(Q3Mesh_NextMeshComponent(&it), TQ3MeshComponent(nullptr)); break;
            }
        }
        return;
    }
    default: {
        // The walks against the counts; the components' vertices.
        if (!counted)
            return;
        checkMeshWalk(mesh, Q3Mesh_FirstMeshVertex, Q3Mesh_NextMeshVertex, before.vertices, "Q3Mesh_NextMeshVertex");
        checkMeshWalk(mesh, Q3Mesh_FirstMeshFace, Q3Mesh_NextMeshFace, before.faces, "Q3Mesh_NextMeshFace");
        checkMeshWalk(mesh, Q3Mesh_FirstMeshEdge, Q3Mesh_NextMeshEdge, before.edges, "Q3Mesh_NextMeshEdge");
        checkMeshWalk(mesh, Q3Mesh_FirstMeshComponent, Q3Mesh_NextMeshComponent, before.components,
                      "Q3Mesh_NextMeshComponent");
        unsigned long inComponents = 0;
        TQ3MeshIterator it;
        for (TQ3MeshComponent c = QUERY(Q3Mesh_FirstMeshComponent(mesh, &it), TQ3MeshComponent(nullptr));
             c != nullptr; c = QUERY(Q3Mesh_NextMeshComponent(&it), TQ3MeshComponent(nullptr))) {
            unsigned long n = 0;
            STATUS(Q3Mesh_GetComponentNumVertices(mesh, c, &n));
            inComponents += n;
        }
        require(inComponents <= before.vertices, "Q3Mesh_GetComponentNumVertices",
                "components hold more vertices than the mesh");
        return;
    }
    }
    if (!counted)
        return;
    MeshCounts after;
    require(meshCounts(mesh, after), call, "a mesh's counts could not be read");
    if (failed) {
        require(after == before && editIndex(mesh) == edit, call, "failed but changed the mesh");
    } else if (action == 1 || action == 2) {
        require(after.vertices == before.vertices && after.faces == before.faces, call,
                "did not add exactly one part");
    } else if (action == 3 || action == 4) {
        require(after.faces <= before.faces + 1, call, "deleted or moved but gained faces");
    }
}

} // namespace q3fuzz
