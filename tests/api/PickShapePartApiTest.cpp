// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Shape parts in picking (QD3DPick.h's ShapePart detail and the
// Q3ShapePart_, Q3MeshPart_ and mesh face/edge/vertex part calls): a pick
// of a mesh under a pick parts style names the face the ray passes
// through, the edge and the vertex it passes next to, each checked against
// the mesh's own handles; under transforms and in window-point picks; and
// every call with bad input.

#include "RenderTestSupport.h"

#include "QD3DGeometry.h"
#include "QD3DPick.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <functional>
#include <vector>

namespace {

using namespace q3test;

using Ends = std::pair<TQ3MeshVertex, TQ3MeshVertex>;

Ends sorted(TQ3MeshVertex a, TQ3MeshVertex b)
{
    return a < b ? Ends{a, b} : Ends{b, a};
}

class PickShapePartApiTest : public Q3ApiTest {
protected:
    void SetUp() override
    {
        Q3ApiTest::SetUp();
        // Two unit squares side by side in z = 0 (faces A and B, sharing the
        // edge from (1, 0) to (1, 1)), and a separate triangle C at x 5..6:
        //   v3 --- v4 --- v5
        //   |  A   |  B   |        C: v6 (5, 0), v7 (6, 0), v8 (5, 1)
        //   v0 --- v1 --- v2
        m_mesh = Q3Mesh_New();
        const TQ3Point3D points[9] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                      {2, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
        for (int i = 0; i < 9; ++i) {
            const TQ3Vertex3D vertex{points[i], nullptr};
            m_v[i] = Q3Mesh_VertexNew(m_mesh, &vertex);
        }
        const TQ3MeshVertex a[4] = {m_v[0], m_v[1], m_v[4], m_v[3]};
        const TQ3MeshVertex b[4] = {m_v[1], m_v[2], m_v[5], m_v[4]};
        const TQ3MeshVertex c[3] = {m_v[6], m_v[7], m_v[8]};
        m_a = Q3Mesh_FaceNew(m_mesh, 4, a, nullptr);
        m_b = Q3Mesh_FaceNew(m_mesh, 4, b, nullptr);
        m_c = Q3Mesh_FaceNew(m_mesh, 3, c, nullptr);
        ASSERT_NE(m_c, nullptr);
        m_view = Q3View_New();
    }

    void TearDown() override
    {
        Q3Object_Dispose(m_view);
        Q3Object_Dispose(m_mesh);
        Q3ApiTest::TearDown();
    }

    // A world-ray pick straight down -z at (x, y), tolerances 0.05, under
    // the pick parts style `parts`, after `before` (transforms); returns
    // the nearest hit's shape part (a new reference) or NULL.
    TQ3ShapePartObject pickPart(float x, float y, TQ3PickParts parts,
                                const std::function<void(TQ3ViewObject)>& before = nullptr)
    {
        TQ3WorldRayPickData data{};
        data.data.sort = kQ3PickSortNearToFar;
        data.data.mask = kQ3PickDetailMaskShapePart | kQ3PickDetailMaskPickPart;
        data.data.numHitsToReturn = kQ3ReturnAllHits;
        data.ray.origin = TQ3Point3D{x, y, 5};
        data.ray.direction = TQ3Vector3D{0, 0, -1};
        data.vertexTolerance = 0.05f;
        data.edgeTolerance = 0.05f;
        TQ3PickObject pick = Q3WorldRayPick_New(&data);
        TQ3ShapePartObject part = runPick(m_view, pick, parts, before);
        Q3Object_Dispose(pick);
        return part;
    }

    TQ3ShapePartObject runPick(TQ3ViewObject view, TQ3PickObject pick, TQ3PickParts parts,
                               const std::function<void(TQ3ViewObject)>& before)
    {
        EXPECT_EQ(Q3View_StartPicking(view, pick), kQ3Success);
        do {
            Q3PickPartsStyle_Submit(parts, view);
            if (before)
                before(view);
            Q3Geometry_Submit(m_mesh, view);
        } while (Q3View_EndPicking(view) == kQ3ViewStatusRetraverse);
        unsigned long n = 0;
        EXPECT_EQ(Q3Pick_GetNumHits(pick, &n), kQ3Success);
        if (n == 0)
            return nullptr;
        TQ3PickDetail valid = 0;
        EXPECT_EQ(Q3Pick_GetPickDetailValidMask(pick, 0, &valid), kQ3Success);
        if ((valid & kQ3PickDetailMaskShapePart) == 0)
            return nullptr;
        TQ3ShapePartObject part = nullptr;
        EXPECT_EQ(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskShapePart, &part), kQ3Success);
        return part;
    }

    TQ3MeshFace faceOf(TQ3ShapePartObject part)
    {
        TQ3MeshFace face = nullptr;
        EXPECT_EQ(Q3MeshFacePart_GetFace(part, &face), kQ3Success);
        return face;
    }

    // The edge's two vertices, in either order, as a sorted pair.
    Ends edgeEnds(TQ3ShapePartObject part)
    {
        TQ3MeshEdge edge = nullptr;
        EXPECT_EQ(Q3MeshEdgePart_GetEdge(part, &edge), kQ3Success);
        TQ3MeshVertex a = nullptr, b = nullptr;
        EXPECT_EQ(Q3Mesh_GetEdgeVertices(m_mesh, edge, &a, &b), kQ3Success);
        return sorted(a, b);
    }

    TQ3GeometryObject m_mesh = nullptr;
    TQ3ViewObject m_view = nullptr;
    TQ3MeshVertex m_v[9] = {};
    TQ3MeshFace m_a = nullptr, m_b = nullptr, m_c = nullptr;
};

TEST_F(PickShapePartApiTest, FacePartNamesTheFaceTheRayPassesThrough)
{
    const struct {
        float x, y;
        TQ3MeshFace face;
    } cases[] = {{0.5f, 0.5f, m_a}, {0.1f, 0.9f, m_a}, {1.5f, 0.3f, m_b}, {1.9f, 0.95f, m_b}, {5.2f, 0.2f, m_c}};
    for (const auto& c : cases) {
        TQ3ShapePartObject part = pickPart(c.x, c.y, kQ3PickPartsMaskFace);
        ASSERT_NE(part, nullptr) << c.x << ", " << c.y;
        EXPECT_EQ(Q3Object_GetLeafType(part), kQ3MeshPartTypeMeshFacePart);
        EXPECT_EQ(Q3ShapePart_GetType(part), kQ3ShapePartTypeMeshPart);
        EXPECT_EQ(Q3MeshPart_GetType(part), kQ3MeshPartTypeMeshFacePart);
        EXPECT_EQ(faceOf(part), c.face) << c.x << ", " << c.y;
        TQ3ShapeObject shape = nullptr;
        ASSERT_EQ(Q3ShapePart_GetShape(part, &shape), kQ3Success);
        EXPECT_EQ(shape, m_mesh);
        Q3Object_Dispose(shape);
        Q3Object_Dispose(part);
    }
    EXPECT_EQ(pickPart(3.0f, 0.5f, kQ3PickPartsMaskFace), nullptr) << "between the components: no hit";
}

TEST_F(PickShapePartApiTest, EdgePartNamesTheEdgeNextToTheRay)
{
    TQ3ShapePartObject part = pickPart(1.02f, 0.5f, kQ3PickPartsMaskEdge);
    ASSERT_NE(part, nullptr);
    EXPECT_EQ(Q3Object_GetLeafType(part), kQ3MeshPartTypeMeshEdgePart);
    EXPECT_EQ(edgeEnds(part), sorted(m_v[1], m_v[4])) << "the shared edge";
    Q3Object_Dispose(part);
    part = pickPart(1.5f, 0.98f, kQ3PickPartsMaskEdge);
    ASSERT_NE(part, nullptr);
    EXPECT_EQ(edgeEnds(part), sorted(m_v[4], m_v[5]));
    Q3Object_Dispose(part);
    part = pickPart(5.49f, 0.52f, kQ3PickPartsMaskEdge);
    ASSERT_NE(part, nullptr);
    EXPECT_EQ(edgeEnds(part), sorted(m_v[7], m_v[8])) << "C's slanted side";
    Q3Object_Dispose(part);
    EXPECT_EQ(pickPart(0.5f, 0.5f, kQ3PickPartsMaskEdge), nullptr) << "no edge within 0.05";
}

TEST_F(PickShapePartApiTest, VertexPartNamesTheVertexAtTheRay)
{
    for (int i : {0, 4, 5, 8}) {
        TQ3Point3D p{};
        ASSERT_EQ(Q3Mesh_GetVertexCoordinates(m_mesh, m_v[i], &p), kQ3Success);
        TQ3ShapePartObject part = pickPart(p.x + 0.01f, p.y - 0.02f, kQ3PickPartsMaskVertex);
        ASSERT_NE(part, nullptr) << i;
        EXPECT_EQ(Q3Object_GetLeafType(part), kQ3MeshPartTypeMeshVertexPart);
        TQ3MeshVertex vertex = nullptr;
        ASSERT_EQ(Q3MeshVertexPart_GetVertex(part, &vertex), kQ3Success);
        EXPECT_EQ(vertex, m_v[i]);
        Q3Object_Dispose(part);
    }
}

TEST_F(PickShapePartApiTest, PartsAreFoundInTheMeshsOwnCoordinates)
{
    // The mesh moved 10 along x and turned a quarter about z: the world
    // point (9.5, 1.5) is the mesh's (1.5, 0.5), inside face B.
    const TQ3Vector3D shift{10, 0, 0};
    auto place = [&](TQ3ViewObject v) {
        Q3TranslateTransform_Submit(&shift, v);
        const TQ3RotateTransformData quarter{kQ3AxisZ, float(M_PI / 2)};
        Q3RotateTransform_Submit(&quarter, v);
    };
    TQ3ShapePartObject part = pickPart(9.5f, 1.5f, kQ3PickPartsMaskFace, place);
    ASSERT_NE(part, nullptr);
    EXPECT_EQ(faceOf(part), m_b);
    Q3Object_Dispose(part);
    part = pickPart(10.0f - 1.0f, 1.0f, kQ3PickPartsMaskVertex, place);
    ASSERT_NE(part, nullptr);
    TQ3MeshVertex vertex = nullptr;
    ASSERT_EQ(Q3MeshVertexPart_GetVertex(part, &vertex), kQ3Success);
    EXPECT_EQ(vertex, m_v[4]) << "(1, 1) turned a quarter about z is (-1, 1)";
    Q3Object_Dispose(part);
}

TEST_F(PickShapePartApiTest, WindowPointPickGivesTheFaceUnderThePixel)
{
    Pixmap image(80, 60);
    TestView view(image.pixmap());
    // listing1OrthographicCamera shows x -0.5..3.5, y -1..2 on 80 x 60
    // pixels: world (1.5, 0.5) is pixel (40, 30).
    TQ3WindowPointPickData data{};
    data.data.sort = kQ3PickSortNearToFar;
    data.data.mask = kQ3PickDetailMaskShapePart;
    data.data.numHitsToReturn = kQ3ReturnAllHits;
    data.point = TQ3Point2D{40.0f, 30.0f};
    data.vertexTolerance = 2.0f;
    data.edgeTolerance = 2.0f;
    TQ3PickObject pick = Q3WindowPointPick_New(&data);
    TQ3ShapePartObject part = runPick(view.view(), pick, kQ3PickPartsMaskFace, nullptr);
    ASSERT_NE(part, nullptr);
    EXPECT_EQ(faceOf(part), m_b);
    TQ3MeshComponent component = nullptr, expected = nullptr;
    ASSERT_EQ(Q3MeshPart_GetComponent(part, &component), kQ3Success);
    ASSERT_EQ(Q3Mesh_GetFaceComponent(m_mesh, m_b, &expected), kQ3Success);
    EXPECT_EQ(component, expected);
    Q3Object_Dispose(part);
    Q3Object_Dispose(pick);
}

TEST_F(PickShapePartApiTest, ComponentIsThePartsComponent)
{
    TQ3MeshComponent ab = nullptr, c = nullptr;
    ASSERT_EQ(Q3Mesh_GetFaceComponent(m_mesh, m_a, &ab), kQ3Success);
    ASSERT_EQ(Q3Mesh_GetFaceComponent(m_mesh, m_c, &c), kQ3Success);
    EXPECT_NE(ab, c);
    // A face inside C, and an edge and a vertex of A.
    const struct {
        float x, y;
        TQ3PickParts mask;
        TQ3MeshComponent component;
    } picks[] = {{5.2f, 0.2f, kQ3PickPartsMaskFace, c},
                 {1.02f, 0.5f, kQ3PickPartsMaskEdge, ab},
                 {0.0f, 0.01f, kQ3PickPartsMaskVertex, ab}};
    for (const auto& pick : picks) {
        TQ3ShapePartObject part = pickPart(pick.x, pick.y, pick.mask);
        ASSERT_NE(part, nullptr) << pick.mask;
        TQ3MeshComponent component = nullptr;
        EXPECT_EQ(Q3MeshPart_GetComponent(part, &component), kQ3Success) << pick.mask;
        EXPECT_EQ(component, pick.component) << pick.mask;
        Q3Object_Dispose(part);
    }
    unsigned long n = 0;
    ASSERT_EQ(Q3Mesh_GetComponentNumVertices(m_mesh, c, &n), kQ3Success) << "a handle the mesh accepts";
    EXPECT_EQ(n, 3u);
}

TEST_F(PickShapePartApiTest, NoShapePartWithoutPartsStyleOrForOtherGeometry)
{
    EXPECT_EQ(pickPart(0.5f, 0.5f, kQ3PickPartsObject), nullptr) << "an object hit has no part";
    // A triangle has no parts: the detail is not valid.
    TQ3TriangleData tri{};
    tri.vertices[1].point = TQ3Point3D{2, 0, 0};
    tri.vertices[2].point = TQ3Point3D{0, 2, 0};
    TQ3GeometryObject triangle = Q3Triangle_New(&tri);
    TQ3WorldRayPickData data{};
    data.data.mask = kQ3PickDetailMaskShapePart;
    data.data.numHitsToReturn = kQ3ReturnAllHits;
    data.ray.origin = TQ3Point3D{0.5f, 0.5f, 5};
    data.ray.direction = TQ3Vector3D{0, 0, -1};
    TQ3PickObject pick = Q3WorldRayPick_New(&data);
    ASSERT_EQ(Q3View_StartPicking(m_view, pick), kQ3Success);
    Q3PickPartsStyle_Submit(kQ3PickPartsMaskFace, m_view);
    Q3Geometry_Submit(triangle, m_view);
    ASSERT_EQ(Q3View_EndPicking(m_view), kQ3ViewStatusDone);
    TQ3PickDetail valid = 1;
    ASSERT_EQ(Q3Pick_GetPickDetailValidMask(pick, 0, &valid), kQ3Success);
    EXPECT_EQ(valid, 0u);
    TQ3Object part = nullptr;
    EXPECT_Q3_ERROR(Q3Pick_GetPickDetailData(pick, 0, kQ3PickDetailMaskShapePart, &part), kQ3ErrorDataNotAvailable);
    Q3Object_Dispose(pick);
    Q3Object_Dispose(triangle);
}

TEST_F(PickShapePartApiTest, CallsRejectBadInput)
{
    TQ3ShapePartObject face = pickPart(0.5f, 0.5f, kQ3PickPartsMaskFace);
    TQ3ShapePartObject edge = pickPart(1.02f, 0.5f, kQ3PickPartsMaskEdge);
    TQ3ShapePartObject vertex = pickPart(1.0f, 1.0f, kQ3PickPartsMaskVertex);
    ASSERT_TRUE(face && edge && vertex);
    TQ3ShapeObject shape = nullptr;
    TQ3MeshComponent component = nullptr;
    TQ3MeshFace f = nullptr;
    TQ3MeshEdge e = nullptr;
    TQ3MeshVertex v = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ShapePart_GetShape(nullptr, &shape), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ShapePart_GetShape(m_mesh, &shape), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ShapePart_GetShape(face, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ShapePart_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ShapePart_GetType(m_view), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(Q3MeshPart_GetType(face), kQ3MeshPartTypeMeshFacePart);
    EXPECT_EQ(Q3MeshPart_GetType(edge), kQ3MeshPartTypeMeshEdgePart);
    EXPECT_EQ(Q3MeshPart_GetType(vertex), kQ3MeshPartTypeMeshVertexPart);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetType(nullptr), kQ3ObjectTypeInvalid), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetType(m_mesh), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetType(m_view), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetComponent(nullptr, &component), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetComponent(m_mesh, &component), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetComponent(face, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    // Each part call takes only its own kind of part.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshFacePart_GetFace(edge, &f), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshFacePart_GetFace(vertex, &f), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshEdgePart_GetEdge(face, &e), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshVertexPart_GetVertex(edge, &v), kQ3Failure), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshFacePart_GetFace(face, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshEdgePart_GetEdge(edge, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshVertexPart_GetVertex(vertex, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshVertexPart_GetVertex(nullptr, &v), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(f, nullptr);
    EXPECT_EQ(e, nullptr);
    EXPECT_EQ(v, nullptr);

    // The part keeps the mesh alive; an edit that deletes its face makes it
    // answer kQ3ErrorInvalidParameter.
    ASSERT_EQ(Q3Mesh_FaceDelete(m_mesh, m_a), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshFacePart_GetFace(face, &f), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetComponent(face, &component), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_EQ(f, nullptr);
    ASSERT_EQ(Q3MeshEdgePart_GetEdge(edge, &e), kQ3Success) << "B still runs along the shared edge";

    Q3Object_Dispose(face);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3ShapePart_GetType(face), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3MeshPart_GetType(face), kQ3ObjectTypeInvalid), kQ3ErrorInvalidObject);
    Q3Object_Dispose(edge);
    Q3Object_Dispose(vertex);
}

} // namespace
