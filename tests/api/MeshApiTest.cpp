// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The Q3Mesh_* calls against QD3DGeometry.h: building and deleting parts,
// counts, indices, boundaries, components and orientation, attribute sets
// of vertices, faces, edges and corners, contours, handles that are deleted,
// of another mesh or of another kind, every iterator and the Q3ForEach
// macros, duplicates, bounds, and the even-odd fill of holed faces checked
// against a point-in-contours test written here.

#include "DiffuseColor.h"
#include "GeometryTestSupport.h"
#include "OwningApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DSet.h"
#include "QD3DView.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <cstdint>
#include <limits>
#include <set>
#include <vector>

namespace {

using namespace q3test;

class MeshApiTest : public OwningApiTest {
protected:
    TQ3GeometryObject newMesh() { return own(Q3Mesh_New()); }

    TQ3MeshVertex vertex(TQ3GeometryObject mesh, float x, float y, float z, TQ3AttributeSet set = nullptr)
    {
        const TQ3Vertex3D v{{x, y, z}, set};
        TQ3MeshVertex made = Q3Mesh_VertexNew(mesh, &v);
        EXPECT_NE(made, nullptr);
        return made;
    }

    TQ3MeshFace face(TQ3GeometryObject mesh, std::vector<TQ3MeshVertex> vertices, TQ3AttributeSet set = nullptr)
    {
        TQ3MeshFace made = Q3Mesh_FaceNew(mesh, static_cast<unsigned long>(vertices.size()), vertices.data(), set);
        EXPECT_NE(made, nullptr);
        return made;
    }

    TQ3AttributeSet colorSet(float r, float g, float b)
    {
        TQ3AttributeSet set = own(Q3AttributeSet_New());
        const TQ3ColorRGB color{r, g, b};
        EXPECT_EQ(Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
        return set;
    }

    // A unit cube, every face counterclockwise seen from outside.
    struct Cube {
        TQ3GeometryObject mesh;
        TQ3MeshVertex v[8];
        TQ3MeshFace f[6];
    };
    Cube cube(bool open = false)
    {
        Cube c{};
        c.mesh = newMesh();
        for (int i = 0; i < 8; ++i)
            c.v[i] = vertex(c.mesh, float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
        const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (int k = 0; k < (open ? 5 : 6); ++k)
            c.f[k] = face(c.mesh, {c.v[faces[k][0]], c.v[faces[k][1]], c.v[faces[k][2]], c.v[faces[k][3]]});
        return c;
    }

    unsigned long count(TQ3Status (*get)(TQ3GeometryObject, unsigned long*), TQ3GeometryObject mesh)
    {
        unsigned long n = 12345;
        EXPECT_EQ(get(mesh, &n), kQ3Success);
        return n;
    }
};

// ---- Building ----------------------------------------------------------

TEST_F(MeshApiTest, NewMakesAnEmptyMesh)
{
    TQ3GeometryObject mesh = newMesh();
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(Q3Geometry_GetType(mesh), kQ3GeometryTypeMesh);
    EXPECT_EQ(Q3Object_IsType(mesh, kQ3ShapeTypeGeometry), kQ3True);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, mesh), 0u);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, mesh), 0u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, mesh), 0u);
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), 0u);
    EXPECT_EQ(count(Q3Mesh_GetNumCorners, mesh), 0u);
    TQ3Boolean orientable = kQ3False;
    EXPECT_EQ(Q3Mesh_GetOrientable(mesh, &orientable), kQ3Success);
    EXPECT_EQ(orientable, kQ3True);
    TQ3MeshIterator it;
    EXPECT_EQ(Q3Mesh_FirstMeshVertex(mesh, &it), nullptr);
    EXPECT_EQ(Q3Mesh_NextMeshVertex(&it), nullptr);
    EXPECT_EQ(Q3Mesh_FirstMeshComponent(mesh, &it), nullptr);
}

TEST_F(MeshApiTest, VertexNewStoresThePointAndTheSet)
{
    TQ3GeometryObject mesh = newMesh();
    TQ3AttributeSet red = colorSet(1, 0, 0);
    TQ3MeshVertex v = vertex(mesh, 1, 2, 3, red);
    TQ3Point3D p{};
    EXPECT_EQ(Q3Mesh_GetVertexCoordinates(mesh, v, &p), kQ3Success);
    EXPECT_EQ(p.x, 1);
    EXPECT_EQ(p.y, 2);
    EXPECT_EQ(p.z, 3);
    TQ3AttributeSet got = nullptr;
    EXPECT_EQ(Q3Mesh_GetVertexAttributeSet(mesh, v, &got), kQ3Success);
    EXPECT_EQ(got, red);
    Q3Object_Dispose(got);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, mesh), 1u);
    // A vertex in no face: no component (a notice), not on a boundary.
    TQ3MeshComponent component = reinterpret_cast<TQ3MeshComponent>(&p);
    EXPECT_Q3_NOTICE(EXPECT_EQ(Q3Mesh_GetVertexComponent(mesh, v, &component), kQ3Success),
                     kQ3NoticeMeshVertexHasNoComponent);
    EXPECT_EQ(component, nullptr);
    TQ3Boolean boundary = kQ3True;
    EXPECT_EQ(Q3Mesh_GetVertexOnBoundary(mesh, v, &boundary), kQ3Success);
    EXPECT_EQ(boundary, kQ3False);
}

TEST_F(MeshApiTest, VertexNewRefusesBadArgumentsAndChangesNothing)
{
    TQ3GeometryObject mesh = newMesh();
    const TQ3Vertex3D good{{0, 0, 0}, nullptr};
    const unsigned long edit = Q3Shared_GetEditIndex(mesh);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexNew(nullptr, &good), nullptr), kQ3ErrorNULLParameter);
    TQ3GeometryObject dead = Q3Mesh_New();
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexNew(dead, &good), nullptr), kQ3ErrorInvalidObject);
    TQ3AttributeSet set = own(Q3AttributeSet_New());
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexNew(set, &good), nullptr), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexNew(mesh, nullptr), nullptr), kQ3ErrorNULLParameter);
    for (float bad : {kNaN, kInf, -kInf}) {
        const TQ3Vertex3D v{{0, bad, 0}, nullptr};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexNew(mesh, &v), nullptr), kQ3ErrorInvalidData);
    }
    const TQ3Vertex3D wrongSet{{0, 0, 0}, mesh};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexNew(mesh, &wrongSet), nullptr), kQ3ErrorInvalidObjectType);
    TQ3AttributeSet deadSet = Q3AttributeSet_New();
    Q3Object_Dispose(deadSet);
    const TQ3Vertex3D deadSetVertex{{0, 0, 0}, deadSet};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexNew(mesh, &deadSetVertex), nullptr), kQ3ErrorInvalidObject);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, mesh), 0u);
    EXPECT_EQ(Q3Shared_GetEditIndex(mesh), edit);
}

TEST_F(MeshApiTest, FaceNewChecksItsArgumentsInOrderAndChangesNothing)
{
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshVertex a = vertex(mesh, 0, 0, 0), b = vertex(mesh, 1, 0, 0), c = vertex(mesh, 0, 1, 0);
    TQ3GeometryObject other = newMesh();
    TQ3MeshVertex foreign = vertex(other, 0, 0, 1);
    TQ3MeshVertex gone = vertex(mesh, 5, 5, 5);
    ASSERT_EQ(Q3Mesh_VertexDelete(mesh, gone), kQ3Success);
    const unsigned long edit = Q3Shared_GetEditIndex(mesh);
    TQ3MeshVertex ring[3] = {a, b, c};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, 3, nullptr, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, 2, ring, nullptr), nullptr),
                    kQ3ErrorGeometryInsufficientNumberOfPoints);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, 0, ring, nullptr), nullptr),
                    kQ3ErrorGeometryInsufficientNumberOfPoints);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, kQ3GeometryMaxArrayCount + 1, ring, nullptr), nullptr),
                    kQ3ErrorParameterOutOfRange);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, 0xFFFFFFFFul, ring, nullptr), nullptr),
                    kQ3ErrorParameterOutOfRange);
    for (TQ3MeshVertex bad : {foreign, gone, reinterpret_cast<TQ3MeshVertex>(std::uintptr_t(0x1234561)),
                              reinterpret_cast<TQ3MeshVertex>(std::uintptr_t(0x40))}) {
        TQ3MeshVertex withBad[3] = {a, bad, c};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, 3, withBad, nullptr), nullptr), kQ3ErrorInvalidParameter);
    }
    TQ3MeshVertex withNull[3] = {a, nullptr, c};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, 3, withNull, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceNew(mesh, 3, ring, mesh), nullptr), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, mesh), 0u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, mesh), 0u);
    EXPECT_EQ(Q3Shared_GetEditIndex(mesh), edit);
    EXPECT_NE(Q3Mesh_FaceNew(mesh, 3, ring, nullptr), nullptr);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, mesh), 3u);
}

// ---- Counts, indices, boundaries, components -----------------------------

TEST_F(MeshApiTest, ACubeHasTwelveSharedEdgesAndIsClosedAndOrientable)
{
    Cube c = cube();
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, c.mesh), 8u);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, c.mesh), 6u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, c.mesh), 12u);
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, c.mesh), 1u);
    TQ3Boolean orientable = kQ3False;
    EXPECT_EQ(Q3Mesh_GetOrientable(c.mesh, &orientable), kQ3Success);
    EXPECT_EQ(orientable, kQ3True);
    TQ3MeshIterator it;
    TQ3MeshEdge e;
    int edges = 0;
    Q3ForEachMeshEdge(c.mesh, e, &it)
    {
        ++edges;
        TQ3Boolean boundary = kQ3True;
        EXPECT_EQ(Q3Mesh_GetEdgeOnBoundary(c.mesh, e, &boundary), kQ3Success);
        EXPECT_EQ(boundary, kQ3False);
        TQ3MeshFace f1 = nullptr, f2 = nullptr;
        EXPECT_EQ(Q3Mesh_GetEdgeFaces(c.mesh, e, &f1, &f2), kQ3Success);
        EXPECT_NE(f1, nullptr);
        EXPECT_NE(f2, nullptr);
        EXPECT_NE(f1, f2);
    }
    EXPECT_EQ(edges, 12);
    for (int i = 0; i < 8; ++i) {
        unsigned long index = 99;
        EXPECT_EQ(Q3Mesh_GetVertexIndex(c.mesh, c.v[i], &index), kQ3Success);
        EXPECT_EQ(index, unsigned(i));
        TQ3Boolean boundary = kQ3True;
        EXPECT_EQ(Q3Mesh_GetVertexOnBoundary(c.mesh, c.v[i], &boundary), kQ3Success);
        EXPECT_EQ(boundary, kQ3False);
    }
    for (int k = 0; k < 6; ++k) {
        unsigned long index = 99, n = 0, contours = 0;
        EXPECT_EQ(Q3Mesh_GetFaceIndex(c.mesh, c.f[k], &index), kQ3Success);
        EXPECT_EQ(index, unsigned(k));
        EXPECT_EQ(Q3Mesh_GetFaceNumVertices(c.mesh, c.f[k], &n), kQ3Success);
        EXPECT_EQ(n, 4u);
        EXPECT_EQ(Q3Mesh_GetFaceNumContours(c.mesh, c.f[k], &contours), kQ3Success);
        EXPECT_EQ(contours, 1u);
    }
}

TEST_F(MeshApiTest, AnOpenBoxHasItsRimOnTheBoundary)
{
    Cube c = cube(true); // no face 5 (x = 1)
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, c.mesh), 12u);
    int boundaryEdges = 0;
    TQ3MeshIterator it;
    TQ3MeshEdge e;
    Q3ForEachMeshEdge(c.mesh, e, &it)
    {
        TQ3Boolean boundary = kQ3False;
        EXPECT_EQ(Q3Mesh_GetEdgeOnBoundary(c.mesh, e, &boundary), kQ3Success);
        boundaryEdges += boundary == kQ3True;
        TQ3MeshFace f1 = nullptr, f2 = c.f[0];
        EXPECT_EQ(Q3Mesh_GetEdgeFaces(c.mesh, e, &f1, &f2), kQ3Success);
        EXPECT_EQ(f2 == nullptr, boundary == kQ3True);
    }
    EXPECT_EQ(boundaryEdges, 4);
    for (int i = 0; i < 8; ++i) {
        TQ3Boolean boundary = kQ3False;
        EXPECT_EQ(Q3Mesh_GetVertexOnBoundary(c.mesh, c.v[i], &boundary), kQ3Success);
        EXPECT_EQ(boundary, (i & 1) ? kQ3True : kQ3False) << i;
    }
}

TEST_F(MeshApiTest, AMoebiusStripIsNotOrientable)
{
    // Four quads in a band whose ends are joined with a half twist.
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshVertex top[4], bottom[4];
    for (int i = 0; i < 4; ++i) {
        const float angle = float(i) * 1.5707963f;
        top[i] = vertex(mesh, std::cos(angle), std::sin(angle), 0.3f);
        bottom[i] = vertex(mesh, std::cos(angle), std::sin(angle), -0.3f);
    }
    for (int i = 0; i < 3; ++i)
        face(mesh, {bottom[i], bottom[i + 1], top[i + 1], top[i]});
    face(mesh, {bottom[3], top[0], bottom[0], top[3]}); // the twist
    TQ3Boolean orientable = kQ3True;
    EXPECT_EQ(Q3Mesh_GetOrientable(mesh, &orientable), kQ3Success);
    EXPECT_EQ(orientable, kQ3False);
    TQ3MeshIterator it;
    TQ3MeshComponent component = Q3Mesh_FirstMeshComponent(mesh, &it);
    ASSERT_NE(component, nullptr);
    EXPECT_EQ(Q3Mesh_GetComponentOrientable(mesh, component, &orientable), kQ3Success);
    EXPECT_EQ(orientable, kQ3False);

    // An edge three faces run along makes a mesh not orientable too.
    TQ3GeometryObject fan = newMesh();
    TQ3MeshVertex a = vertex(fan, 0, 0, 0), b = vertex(fan, 0, 0, 1);
    for (int i = 0; i < 3; ++i)
        face(fan, {a, b, vertex(fan, std::cos(float(i) * 2), std::sin(float(i) * 2), 0.5f)});
    orientable = kQ3True;
    EXPECT_EQ(Q3Mesh_GetOrientable(fan, &orientable), kQ3Success);
    EXPECT_EQ(orientable, kQ3False);

    // Two triangles sharing an edge the same way round can be flipped.
    TQ3GeometryObject pair = newMesh();
    TQ3MeshVertex p = vertex(pair, 0, 0, 0), q = vertex(pair, 1, 0, 0);
    face(pair, {p, q, vertex(pair, 0, 1, 0)});
    face(pair, {p, q, vertex(pair, 0, -1, 0)});
    orientable = kQ3False;
    EXPECT_EQ(Q3Mesh_GetOrientable(pair, &orientable), kQ3Success);
    EXPECT_EQ(orientable, kQ3True);
}

TEST_F(MeshApiTest, ComponentsAreTheConnectedSetsOfFaces)
{
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshVertex a = vertex(mesh, 0, 0, 0), b = vertex(mesh, 1, 0, 0), c = vertex(mesh, 0, 1, 0);
    TQ3MeshVertex d = vertex(mesh, 5, 5, 5), e = vertex(mesh, 6, 5, 5), f = vertex(mesh, 5, 7, 4);
    TQ3MeshVertex lonely = vertex(mesh, 9, 9, 9);
    TQ3MeshFace left = face(mesh, {a, b, c});
    TQ3MeshFace right = face(mesh, {d, e, f});
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), 2u);
    TQ3MeshComponent cl = nullptr, cr = nullptr, ce = nullptr;
    EXPECT_EQ(Q3Mesh_GetFaceComponent(mesh, left, &cl), kQ3Success);
    EXPECT_EQ(Q3Mesh_GetFaceComponent(mesh, right, &cr), kQ3Success);
    EXPECT_NE(cl, cr);
    TQ3MeshComponent cv = nullptr;
    EXPECT_EQ(Q3Mesh_GetVertexComponent(mesh, b, &cv), kQ3Success);
    EXPECT_EQ(cv, cl);
    TQ3MeshIterator it;
    TQ3MeshEdge edge = Q3Mesh_FirstMeshEdge(mesh, &it);
    EXPECT_EQ(Q3Mesh_GetEdgeComponent(mesh, edge, &ce), kQ3Success);
    EXPECT_EQ(ce, cl);
    unsigned long n = 0;
    EXPECT_EQ(Q3Mesh_GetComponentNumVertices(mesh, cr, &n), kQ3Success);
    EXPECT_EQ(n, 3u);
    EXPECT_EQ(Q3Mesh_GetComponentNumEdges(mesh, cr, &n), kQ3Success);
    EXPECT_EQ(n, 3u);
    TQ3BoundingBox box{};
    EXPECT_EQ(Q3Mesh_GetComponentBoundingBox(mesh, cr, &box), kQ3Success);
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_EQ(box.min.x, 5);
    EXPECT_EQ(box.min.y, 5);
    EXPECT_EQ(box.min.z, 4);
    EXPECT_EQ(box.max.x, 6);
    EXPECT_EQ(box.max.y, 7);
    EXPECT_EQ(box.max.z, 5);
    TQ3Boolean orientable = kQ3False;
    EXPECT_EQ(Q3Mesh_GetComponentOrientable(mesh, cl, &orientable), kQ3Success);
    EXPECT_EQ(orientable, kQ3True);
    EXPECT_Q3_NOTICE(EXPECT_EQ(Q3Mesh_GetVertexComponent(mesh, lonely, &cv), kQ3Success),
                     kQ3NoticeMeshVertexHasNoComponent);
    EXPECT_EQ(cv, nullptr);

    // Joining the two merges them; the later one's handle is retired and
    // refused, unchanged outputs and all.
    face(mesh, {c, d, b});
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), 1u);
    n = 77;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetComponentNumVertices(mesh, cr, &n), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_EQ(n, 77u);
    EXPECT_EQ(Q3Mesh_GetComponentNumVertices(mesh, cl, &n), kQ3Success);
    EXPECT_EQ(n, 6u);
    EXPECT_EQ(Q3Mesh_GetComponentNumEdges(mesh, cl, &n), kQ3Success);
    EXPECT_EQ(n, 8u);
}

// ---- Deleting and handles --------------------------------------------------

TEST_F(MeshApiTest, DeletingAVertexDeletesItsFacesAndRenumbers)
{
    Cube c = cube();
    ASSERT_EQ(Q3Mesh_VertexDelete(c.mesh, c.v[0]), kQ3Success);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, c.mesh), 7u);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, c.mesh), 3u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, c.mesh), 9u);
    unsigned long index = 0;
    EXPECT_EQ(Q3Mesh_GetVertexIndex(c.mesh, c.v[7], &index), kQ3Success);
    EXPECT_EQ(index, 6u);
    EXPECT_EQ(Q3Mesh_GetFaceIndex(c.mesh, c.f[1], &index), kQ3Success);
    EXPECT_EQ(index, 0u);
    index = 42;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexIndex(c.mesh, c.v[0], &index), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFaceIndex(c.mesh, c.f[0], &index), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_EQ(index, 42u);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexDelete(c.mesh, c.v[0]), kQ3Failure), kQ3ErrorInvalidParameter);

    ASSERT_EQ(Q3Mesh_FaceDelete(c.mesh, c.f[1]), kQ3Success);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, c.mesh), 7u);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, c.mesh), 2u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, c.mesh), 7u);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceDelete(c.mesh, c.f[1]), kQ3Failure), kQ3ErrorInvalidParameter);
}

TEST_F(MeshApiTest, HandlesOfOtherMeshesKindsOrNoPartAreRefusedAndNothingChanges)
{
    Cube c = cube();
    Cube d = cube();
    const unsigned long edit = Q3Shared_GetEditIndex(c.mesh);
    TQ3MeshIterator it;
    TQ3MeshEdge edge = Q3Mesh_FirstMeshEdge(c.mesh, &it);
    TQ3MeshContour contour = Q3Mesh_FirstFaceContour(c.f[0], &it);
    const std::vector<TQ3MeshVertex> badVertices = {
        d.v[0], reinterpret_cast<TQ3MeshVertex>(c.f[0]), reinterpret_cast<TQ3MeshVertex>(edge),
        reinterpret_cast<TQ3MeshVertex>(contour), reinterpret_cast<TQ3MeshVertex>(std::uintptr_t(1)),
        reinterpret_cast<TQ3MeshVertex>(&it), reinterpret_cast<TQ3MeshVertex>(~std::uintptr_t(0))};
    for (TQ3MeshVertex bad : badVertices) {
        TQ3Point3D p{7, 7, 7};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexCoordinates(c.mesh, bad, &p), kQ3Failure), kQ3ErrorInvalidParameter);
        EXPECT_EQ(p.x, 7);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetVertexCoordinates(c.mesh, bad, &p), kQ3Failure), kQ3ErrorInvalidParameter);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_VertexDelete(c.mesh, bad), kQ3Failure), kQ3ErrorInvalidParameter);
        if (bad != d.v[0]) // another mesh's vertex is a vertex where no mesh is passed
            EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FirstVertexEdge(bad, &it), nullptr), kQ3ErrorInvalidParameter);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceDelete(c.mesh, d.f[0]), kQ3Failure), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceDelete(c.mesh, reinterpret_cast<TQ3MeshFace>(c.v[0])), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceDelete(c.mesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_ContourToFace(c.mesh, reinterpret_cast<TQ3MeshContour>(edge)), nullptr),
                    kQ3ErrorInvalidParameter);
    EXPECT_EQ(Q3Shared_GetEditIndex(c.mesh), edit);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, c.mesh), 6u);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, c.mesh), 8u);
}

TEST_F(MeshApiTest, PartsOfADisposedMeshAreRefusedWhereNoMeshIsPassed)
{
    TQ3GeometryObject mesh = Q3Mesh_New();
    TQ3MeshVertex a = vertex(mesh, 0, 0, 0), b = vertex(mesh, 1, 0, 0), c = vertex(mesh, 0, 1, 0);
    TQ3MeshFace f = face(mesh, {a, b, c});
    TQ3MeshIterator it;
    ASSERT_NE(Q3Mesh_FirstFaceVertex(f, &it), nullptr);
    TQ3MeshIterator walk;
    ASSERT_NE(Q3Mesh_FirstMeshVertex(mesh, &walk), nullptr);
    Q3Object_Dispose(mesh);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_NextFaceVertex(&it), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_EQ(Q3Mesh_NextFaceVertex(&it), nullptr); // ended: no further error
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_NextMeshVertex(&walk), nullptr), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FirstVertexFace(a, &it), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FirstFaceEdge(f, &it), nullptr), kQ3ErrorInvalidParameter);
}

// ---- Vertices, faces, contours -------------------------------------------

TEST_F(MeshApiTest, SetVertexCoordinatesMovesAndRefusesNonFinitePoints)
{
    Cube c = cube();
    const TQ3Point3D moved{2, 3, 4};
    EXPECT_EQ(Q3Mesh_SetVertexCoordinates(c.mesh, c.v[5], &moved), kQ3Success);
    TQ3Point3D p{};
    EXPECT_EQ(Q3Mesh_GetVertexCoordinates(c.mesh, c.v[5], &p), kQ3Success);
    EXPECT_EQ(p.x, 2);
    EXPECT_EQ(p.z, 4);
    const unsigned long edit = Q3Shared_GetEditIndex(c.mesh);
    for (float bad : {kNaN, kInf, -kInf}) {
        const TQ3Point3D q{bad, 0, 0};
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetVertexCoordinates(c.mesh, c.v[5], &q), kQ3Failure), kQ3ErrorInvalidData);
    }
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetVertexCoordinates(c.mesh, c.v[5], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexCoordinates(c.mesh, c.v[5], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Shared_GetEditIndex(c.mesh), edit);
    EXPECT_EQ(Q3Mesh_GetVertexCoordinates(c.mesh, c.v[5], &p), kQ3Success);
    EXPECT_EQ(p.y, 3);
}

TEST_F(MeshApiTest, FacePlaneEquationIsTheFirstContoursPlane)
{
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshFace f = face(mesh, {vertex(mesh, 0, 0, 2), vertex(mesh, 2, 0, 2), vertex(mesh, 2, 3, 2),
                                vertex(mesh, 0, 3, 2)});
    TQ3PlaneEquation plane{};
    EXPECT_EQ(Q3Mesh_GetFacePlaneEquation(mesh, f, &plane), kQ3Success);
    EXPECT_NEAR(plane.normal.x, 0, 1e-6);
    EXPECT_NEAR(plane.normal.y, 0, 1e-6);
    EXPECT_NEAR(plane.normal.z, 1, 1e-6);
    EXPECT_NEAR(plane.constant, -2, 1e-6);
    TQ3MeshFace flat = face(mesh, {vertex(mesh, 0, 0, 0), vertex(mesh, 1, 1, 1), vertex(mesh, 2, 2, 2)});
    plane.constant = 9;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFacePlaneEquation(mesh, flat, &plane), kQ3Failure),
                    kQ3ErrorDegenerateGeometry);
    EXPECT_EQ(plane.constant, 9);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFacePlaneEquation(mesh, f, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
}

TEST_F(MeshApiTest, FaceToContourMakesAHoleAndContourToFaceTakesItOut)
{
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshFace outer = face(mesh, {vertex(mesh, 0, 0, 0), vertex(mesh, 4, 0, 0), vertex(mesh, 4, 4, 0),
                                    vertex(mesh, 0, 4, 0)}, colorSet(1, 0, 0));
    TQ3MeshFace inner = face(mesh, {vertex(mesh, 1, 1, 0), vertex(mesh, 1, 3, 0), vertex(mesh, 3, 3, 0)},
                             colorSet(0, 1, 0));
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FaceToContour(mesh, outer, outer), nullptr), kQ3ErrorInvalidParameter);
    TQ3MeshContour hole = Q3Mesh_FaceToContour(mesh, outer, inner);
    ASSERT_NE(hole, nullptr);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, mesh), 1u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, mesh), 7u);
    unsigned long n = 0;
    EXPECT_EQ(Q3Mesh_GetFaceNumContours(mesh, outer, &n), kQ3Success);
    EXPECT_EQ(n, 2u);
    EXPECT_EQ(Q3Mesh_GetFaceNumVertices(mesh, outer, &n), kQ3Success);
    EXPECT_EQ(n, 7u);
    EXPECT_EQ(Q3Mesh_GetContourNumVertices(mesh, hole, &n), kQ3Success);
    EXPECT_EQ(n, 3u);
    TQ3MeshFace owner = nullptr;
    EXPECT_EQ(Q3Mesh_GetContourFace(mesh, hole, &owner), kQ3Success);
    EXPECT_EQ(owner, outer);
    unsigned long index = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFaceIndex(mesh, inner, &index), kQ3Failure), kQ3ErrorInvalidParameter);
    // One component (the contours share the face), still.
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), 1u);

    TQ3MeshFace back = Q3Mesh_ContourToFace(mesh, hole);
    ASSERT_NE(back, nullptr);
    EXPECT_NE(back, outer);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, mesh), 2u);
    EXPECT_EQ(Q3Mesh_GetFaceNumContours(mesh, outer, &n), kQ3Success);
    EXPECT_EQ(n, 1u);
    EXPECT_EQ(Q3Mesh_GetContourFace(mesh, hole, &owner), kQ3Success);
    EXPECT_EQ(owner, back);
    TQ3AttributeSet set = view();
    EXPECT_EQ(Q3Mesh_GetFaceAttributeSet(mesh, back, &set), kQ3Success);
    EXPECT_EQ(set, nullptr);
    // A face's only contour is that face already.
    EXPECT_EQ(Q3Mesh_ContourToFace(mesh, hole), back);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, mesh), 2u);
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), 2u);
}

// ---- Attribute sets ------------------------------------------------------

TEST_F(MeshApiTest, VertexFaceEdgeAndCornerSetsRoundTripAndNullRemovesThem)
{
    Cube c = cube();
    TQ3AttributeSet red = colorSet(1, 0, 0);
    TQ3MeshIterator it;
    TQ3MeshEdge edge = Q3Mesh_FirstMeshEdge(c.mesh, &it);
    TQ3AttributeSet got = nullptr;

    EXPECT_EQ(Q3Mesh_SetVertexAttributeSet(c.mesh, c.v[1], red), kQ3Success);
    EXPECT_EQ(Q3Mesh_GetVertexAttributeSet(c.mesh, c.v[1], &got), kQ3Success);
    EXPECT_EQ(got, red);
    Q3Object_Dispose(got);
    EXPECT_EQ(Q3Mesh_SetFaceAttributeSet(c.mesh, c.f[2], red), kQ3Success);
    EXPECT_EQ(Q3Mesh_GetFaceAttributeSet(c.mesh, c.f[2], &got), kQ3Success);
    EXPECT_EQ(got, red);
    Q3Object_Dispose(got);
    EXPECT_EQ(Q3Mesh_SetEdgeAttributeSet(c.mesh, edge, red), kQ3Success);
    EXPECT_EQ(Q3Mesh_GetEdgeAttributeSet(c.mesh, edge, &got), kQ3Success);
    EXPECT_EQ(got, red);
    Q3Object_Dispose(got);
    EXPECT_EQ(Q3Mesh_SetCornerAttributeSet(c.mesh, c.v[0], c.f[0], red), kQ3Success);
    EXPECT_EQ(Q3Mesh_GetCornerAttributeSet(c.mesh, c.v[0], c.f[0], &got), kQ3Success);
    EXPECT_EQ(got, red);
    Q3Object_Dispose(got);
    EXPECT_EQ(Q3Mesh_GetCornerAttributeSet(c.mesh, c.v[0], c.f[2], &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    EXPECT_EQ(count(Q3Mesh_GetNumCorners, c.mesh), 1u);

    // The mesh holds its own references: the sets outlive the caller's.
    const unsigned long live = Q3Memory_CountLiveObjects();
    EXPECT_EQ(Q3Mesh_SetVertexAttributeSet(c.mesh, c.v[1], nullptr), kQ3Success);
    EXPECT_EQ(Q3Mesh_SetFaceAttributeSet(c.mesh, c.f[2], nullptr), kQ3Success);
    EXPECT_EQ(Q3Mesh_SetEdgeAttributeSet(c.mesh, edge, nullptr), kQ3Success);
    EXPECT_EQ(Q3Mesh_SetCornerAttributeSet(c.mesh, c.v[0], c.f[0], nullptr), kQ3Success);
    EXPECT_EQ(Q3Memory_CountLiveObjects(), live);
    EXPECT_EQ(count(Q3Mesh_GetNumCorners, c.mesh), 0u);
    got = red;
    EXPECT_EQ(Q3Mesh_GetVertexAttributeSet(c.mesh, c.v[1], &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
    got = red;
    EXPECT_EQ(Q3Mesh_GetEdgeAttributeSet(c.mesh, edge, &got), kQ3Success);
    EXPECT_EQ(got, nullptr);
}

TEST_F(MeshApiTest, AttributeSetSettersRefuseBadSetsAndStrangersAndChangeNothing)
{
    Cube c = cube();
    TQ3MeshIterator it;
    TQ3MeshEdge edge = Q3Mesh_FirstMeshEdge(c.mesh, &it);
    TQ3AttributeSet dead = Q3AttributeSet_New();
    Q3Object_Dispose(dead);
    const unsigned long edit = Q3Shared_GetEditIndex(c.mesh);
    for (TQ3Object bad : {static_cast<TQ3Object>(dead), static_cast<TQ3Object>(c.mesh)}) {
        const TQ3Error code = bad == dead ? kQ3ErrorInvalidObject : kQ3ErrorInvalidObjectType;
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetVertexAttributeSet(c.mesh, c.v[0], bad), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetFaceAttributeSet(c.mesh, c.f[0], bad), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetEdgeAttributeSet(c.mesh, edge, bad), kQ3Failure), code);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetCornerAttributeSet(c.mesh, c.v[0], c.f[0], bad), kQ3Failure), code);
    }
    // v[7] is not a corner of f[0] (z = 0 face).
    TQ3AttributeSet got = c.mesh;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetCornerAttributeSet(c.mesh, c.v[7], c.f[0], &got), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_EQ(got, c.mesh);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_SetCornerAttributeSet(c.mesh, c.v[7], c.f[0], nullptr), kQ3Failure),
                    kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexAttributeSet(c.mesh, c.v[0], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFaceAttributeSet(c.mesh, nullptr, &got), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetEdgeAttributeSet(c.mesh, edge, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetCornerAttributeSet(c.mesh, c.v[0], c.f[0], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_EQ(Q3Shared_GetEditIndex(c.mesh), edit);
}

TEST_F(MeshApiTest, EveryGetterRefusesNullOutputsAndKeepsThemUnchanged)
{
    Cube c = cube();
    TQ3MeshIterator it;
    TQ3MeshEdge edge = Q3Mesh_FirstMeshEdge(c.mesh, &it);
    TQ3MeshComponent comp = Q3Mesh_FirstMeshComponent(c.mesh, &it);
    TQ3MeshContour contour = Q3Mesh_FirstFaceContour(c.f[0], &it);
    TQ3MeshVertex v = nullptr;
    TQ3MeshFace f = nullptr;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetNumComponents(c.mesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetNumEdges(nullptr, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetNumVertices(c.mesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetNumFaces(c.mesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetNumCorners(c.mesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetOrientable(c.mesh, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetComponentNumVertices(c.mesh, comp, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetComponentNumEdges(c.mesh, nullptr, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetComponentBoundingBox(c.mesh, comp, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetComponentOrientable(c.mesh, comp, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexIndex(c.mesh, c.v[0], nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexOnBoundary(c.mesh, c.v[0], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexComponent(c.mesh, c.v[0], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFaceNumVertices(c.mesh, c.f[0], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFaceNumContours(c.mesh, c.f[0], nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFaceIndex(c.mesh, c.f[0], nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetFaceComponent(c.mesh, c.f[0], nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetEdgeVertices(c.mesh, edge, &v, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(v, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetEdgeFaces(c.mesh, edge, nullptr, &f), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_EQ(f, nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetEdgeOnBoundary(c.mesh, edge, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetEdgeComponent(c.mesh, edge, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetContourFace(c.mesh, contour, nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetContourNumVertices(c.mesh, contour, nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_DelayUpdates(nullptr), kQ3Failure), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_ResumeUpdates(reinterpret_cast<TQ3GeometryObject>(c.f[0])), kQ3Failure), kQ3ErrorInvalidObject);
}

TEST_F(MeshApiTest, EdgeVerticesFollowTheContourThatMadeTheEdge)
{
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshVertex a = vertex(mesh, 0, 0, 0), b = vertex(mesh, 1, 0, 0), c = vertex(mesh, 0, 1, 0);
    TQ3MeshVertex d = vertex(mesh, 1, 1, 0);
    TQ3MeshFace first = face(mesh, {a, b, c});
    TQ3MeshFace second = face(mesh, {c, b, d});
    TQ3MeshIterator it;
    TQ3MeshEdge e;
    int shared = 0;
    Q3ForEachMeshEdge(mesh, e, &it)
    {
        TQ3MeshVertex v1 = nullptr, v2 = nullptr;
        TQ3MeshFace f1 = nullptr, f2 = nullptr;
        ASSERT_EQ(Q3Mesh_GetEdgeVertices(mesh, e, &v1, &v2), kQ3Success);
        ASSERT_EQ(Q3Mesh_GetEdgeFaces(mesh, e, &f1, &f2), kQ3Success);
        if (f2 != nullptr) {
            ++shared;
            EXPECT_EQ(v1, b);
            EXPECT_EQ(v2, c);
            EXPECT_EQ(f1, first);
            EXPECT_EQ(f2, second);
        }
    }
    EXPECT_EQ(shared, 1);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, mesh), 5u);
}

TEST_F(MeshApiTest, DelayAndResumeUpdatesChangeNoResult)
{
    TQ3GeometryObject mesh = newMesh();
    EXPECT_EQ(Q3Mesh_ResumeUpdates(mesh), kQ3Success);
    EXPECT_EQ(Q3Mesh_DelayUpdates(mesh), kQ3Success);
    TQ3MeshVertex a = vertex(mesh, 0, 0, 0), b = vertex(mesh, 1, 0, 0), c = vertex(mesh, 0, 1, 0);
    face(mesh, {a, b, c});
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), 1u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, mesh), 3u);
    EXPECT_EQ(Q3Mesh_ResumeUpdates(mesh), kQ3Success);
    EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), 1u);
}

// A grid of quads with faces deleted at random (fixed seeds): the counts,
// boundaries and components agree with a model of the grid kept here (edge
// sets and a union-find over the remaining quads).
TEST_F(MeshApiTest, RandomlyHoledGridsAgreeWithAnIndependentModel)
{
    constexpr int kN = 7;
    for (unsigned seed = 1; seed <= 12; ++seed) {
        std::mt19937 random(seed);
        TQ3GeometryObject mesh = newMesh();
        std::vector<TQ3MeshVertex> v;
        for (int y = 0; y <= kN; ++y)
            for (int x = 0; x <= kN; ++x)
                v.push_back(vertex(mesh, float(x), float(y), float((x * y) % 3) * 0.1f));
        auto at = [&](int x, int y) { return y * (kN + 1) + x; };
        std::vector<std::array<int, 4>> quads;
        std::vector<TQ3MeshFace> faces;
        for (int y = 0; y < kN; ++y)
            for (int x = 0; x < kN; ++x) {
                quads.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1)});
                faces.push_back(face(mesh, {v[at(x, y)], v[at(x + 1, y)], v[at(x + 1, y + 1)], v[at(x, y + 1)]}));
            }
        std::vector<bool> alive(quads.size(), true);
        for (std::size_t i = 0; i < quads.size(); ++i)
            if (random() % 3 == 0) {
                ASSERT_EQ(Q3Mesh_FaceDelete(mesh, faces[i]), kQ3Success);
                alive[i] = false;
            }
        // The model.
        std::map<std::pair<int, int>, int> uses;
        std::vector<int> parent(v.size());
        for (std::size_t i = 0; i < parent.size(); ++i)
            parent[i] = int(i);
        std::function<int(int)> find = [&](int a) { return parent[a] == a ? a : parent[a] = find(parent[a]); };
        std::set<int> used;
        std::size_t liveFaces = 0;
        for (std::size_t i = 0; i < quads.size(); ++i) {
            if (!alive[i])
                continue;
            ++liveFaces;
            for (int k = 0; k < 4; ++k) {
                const int a = quads[i][k], b = quads[i][(k + 1) % 4];
                ++uses[{std::min(a, b), std::max(a, b)}];
                parent[find(a)] = find(b);
                used.insert(a);
            }
        }
        std::set<int> roots, onBoundary;
        for (int a : used)
            roots.insert(find(a));
        for (const auto& u : uses)
            if (u.second == 1) {
                onBoundary.insert(u.first.first);
                onBoundary.insert(u.first.second);
            }
        EXPECT_EQ(count(Q3Mesh_GetNumFaces, mesh), liveFaces) << seed;
        EXPECT_EQ(count(Q3Mesh_GetNumEdges, mesh), uses.size()) << seed;
        EXPECT_EQ(count(Q3Mesh_GetNumComponents, mesh), roots.size()) << seed;
        for (std::size_t i = 0; i < v.size(); ++i) {
            TQ3Boolean boundary = kQ3False;
            ASSERT_EQ(Q3Mesh_GetVertexOnBoundary(mesh, v[i], &boundary), kQ3Success);
            EXPECT_EQ(boundary == kQ3True, onBoundary.count(int(i)) == 1) << seed << " vertex " << i;
        }
        // Every component's vertices, summed, are the vertices in faces;
        // each vertex's component is the one that walks over it.
        TQ3MeshIterator it, inner;
        TQ3MeshComponent c;
        std::size_t inComponents = 0;
        Q3ForEachMeshComponent(mesh, c, &it)
        {
            unsigned long n = 0;
            ASSERT_EQ(Q3Mesh_GetComponentNumVertices(mesh, c, &n), kQ3Success);
            inComponents += n;
            TQ3MeshVertex w;
            Q3ForEachComponentVertex(c, w, &inner)
            {
                TQ3MeshComponent own = nullptr;
                ASSERT_EQ(Q3Mesh_GetVertexComponent(mesh, w, &own), kQ3Success);
                EXPECT_EQ(own, c);
            }
            TQ3Boolean orientable = kQ3False;
            ASSERT_EQ(Q3Mesh_GetComponentOrientable(mesh, c, &orientable), kQ3Success);
            EXPECT_EQ(orientable, kQ3True);
        }
        EXPECT_EQ(inComponents, used.size()) << seed;
    }
}

// ---- Iterators -----------------------------------------------------------

template <class Handle, class First, class Next, class Owner>
std::vector<Handle> walk(First first, Next next, Owner owner)
{
    std::vector<Handle> seen;
    TQ3MeshIterator it;
    for (Handle h = first(owner, &it); h != nullptr; h = next(&it))
        seen.push_back(h);
    return seen;
}

template <class Handle>
bool distinct(const std::vector<Handle>& list)
{
    return std::set<Handle>(list.begin(), list.end()).size() == list.size();
}

TEST_F(MeshApiTest, EveryWalkGivesEachPartOnce)
{
    Cube c = cube();
    TQ3GeometryObject m = c.mesh;
    auto vertices = walk<TQ3MeshVertex>(Q3Mesh_FirstMeshVertex, Q3Mesh_NextMeshVertex, m);
    ASSERT_EQ(vertices.size(), 8u);
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(vertices[i], c.v[i]);
    auto faces = walk<TQ3MeshFace>(Q3Mesh_FirstMeshFace, Q3Mesh_NextMeshFace, m);
    ASSERT_EQ(faces.size(), 6u);
    for (int k = 0; k < 6; ++k)
        EXPECT_EQ(faces[k], c.f[k]);
    auto edges = walk<TQ3MeshEdge>(Q3Mesh_FirstMeshEdge, Q3Mesh_NextMeshEdge, m);
    EXPECT_EQ(edges.size(), 12u);
    EXPECT_TRUE(distinct(edges));
    auto components = walk<TQ3MeshComponent>(Q3Mesh_FirstMeshComponent, Q3Mesh_NextMeshComponent, m);
    ASSERT_EQ(components.size(), 1u);
    auto cv = walk<TQ3MeshVertex>(Q3Mesh_FirstComponentVertex, Q3Mesh_NextComponentVertex, components[0]);
    EXPECT_EQ(cv, vertices);
    auto ce = walk<TQ3MeshEdge>(Q3Mesh_FirstComponentEdge, Q3Mesh_NextComponentEdge, components[0]);
    EXPECT_EQ(ce, edges);

    // Each cube vertex: three edges, three neighbours (those differing in
    // one coordinate bit), three faces.
    for (int i = 0; i < 8; ++i) {
        auto ve = walk<TQ3MeshEdge>(Q3Mesh_FirstVertexEdge, Q3Mesh_NextVertexEdge, c.v[i]);
        EXPECT_EQ(ve.size(), 3u);
        EXPECT_TRUE(distinct(ve));
        for (TQ3MeshEdge e : ve) {
            TQ3MeshVertex v1, v2;
            ASSERT_EQ(Q3Mesh_GetEdgeVertices(m, e, &v1, &v2), kQ3Success);
            EXPECT_TRUE(v1 == c.v[i] || v2 == c.v[i]);
        }
        auto vv = walk<TQ3MeshVertex>(Q3Mesh_FirstVertexVertex, Q3Mesh_NextVertexVertex, c.v[i]);
        std::set<TQ3MeshVertex> expected{c.v[i ^ 1], c.v[i ^ 2], c.v[i ^ 4]};
        EXPECT_EQ(std::set<TQ3MeshVertex>(vv.begin(), vv.end()), expected);
        EXPECT_EQ(vv.size(), 3u);
        auto vf = walk<TQ3MeshFace>(Q3Mesh_FirstVertexFace, Q3Mesh_NextVertexFace, c.v[i]);
        EXPECT_EQ(vf.size(), 3u);
        EXPECT_TRUE(distinct(vf));
    }
    // Each face: four edges, four corners, four neighbours, one contour.
    for (int k = 0; k < 6; ++k) {
        auto fe = walk<TQ3MeshEdge>(Q3Mesh_FirstFaceEdge, Q3Mesh_NextFaceEdge, c.f[k]);
        EXPECT_EQ(fe.size(), 4u);
        EXPECT_TRUE(distinct(fe));
        auto fv = walk<TQ3MeshVertex>(Q3Mesh_FirstFaceVertex, Q3Mesh_NextFaceVertex, c.f[k]);
        EXPECT_EQ(fv.size(), 4u);
        EXPECT_TRUE(distinct(fv));
        auto ff = walk<TQ3MeshFace>(Q3Mesh_FirstFaceFace, Q3Mesh_NextFaceFace, c.f[k]);
        EXPECT_EQ(ff.size(), 4u);
        EXPECT_TRUE(distinct(ff));
        EXPECT_EQ(std::count(ff.begin(), ff.end(), c.f[k]), 0);
        EXPECT_EQ(std::count(ff.begin(), ff.end(), c.f[k ^ 1]), 0); // the opposite face
        auto fc = walk<TQ3MeshContour>(Q3Mesh_FirstFaceContour, Q3Mesh_NextFaceContour, c.f[k]);
        ASSERT_EQ(fc.size(), 1u);
        auto hv = walk<TQ3MeshVertex>(Q3Mesh_FirstContourVertex, Q3Mesh_NextContourVertex, fc[0]);
        EXPECT_EQ(hv, fv);
        auto he = walk<TQ3MeshEdge>(Q3Mesh_FirstContourEdge, Q3Mesh_NextContourEdge, fc[0]);
        EXPECT_EQ(he, fe);
        auto hf = walk<TQ3MeshFace>(Q3Mesh_FirstContourFace, Q3Mesh_NextContourFace, fc[0]);
        EXPECT_EQ(hf, ff);
    }
}

TEST_F(MeshApiTest, TheForEachMacrosWalkAsTheFunctionsDo)
{
    Cube c = cube();
    TQ3MeshIterator i, j;
    TQ3MeshComponent comp;
    TQ3MeshVertex v, n;
    TQ3MeshFace f, g;
    TQ3MeshEdge e;
    TQ3MeshContour h;
    int components = 0, componentVertices = 0, componentEdges = 0, vertices = 0, faces = 0, edges = 0;
    Q3ForEachMeshComponent(c.mesh, comp, &i)
    {
        ++components;
        Q3ForEachComponentVertex(comp, v, &j) ++componentVertices;
        Q3ForEachComponentEdge(comp, e, &j) ++componentEdges;
    }
    int vertexEdges = 0, vertexVertices = 0, vertexFaces = 0;
    Q3ForEachMeshVertex(c.mesh, v, &i)
    {
        ++vertices;
        Q3ForEachVertexEdge(v, e, &j) ++vertexEdges;
        Q3ForEachVertexVertex(v, n, &j) ++vertexVertices;
        Q3ForEachVertexFace(v, f, &j) ++vertexFaces;
    }
    int faceEdges = 0, faceVertices = 0, faceFaces = 0, faceContours = 0, contourEdges = 0, contourVertices = 0,
        contourFaces = 0;
    Q3ForEachMeshFace(c.mesh, f, &i)
    {
        ++faces;
        Q3ForEachFaceEdge(f, e, &j) ++faceEdges;
        Q3ForEachFaceVertex(f, v, &j) ++faceVertices;
        Q3ForEachFaceFace(f, g, &j) ++faceFaces;
        TQ3MeshIterator k;
        Q3ForEachFaceContour(f, h, &j)
        {
            ++faceContours;
            Q3ForEachContourEdge(h, e, &k) ++contourEdges;
            Q3ForEachContourVertex(h, v, &k) ++contourVertices;
            Q3ForEachContourFace(h, g, &k) ++contourFaces;
        }
    }
    Q3ForEachMeshEdge(c.mesh, e, &i) ++edges;
    EXPECT_EQ(components, 1);
    EXPECT_EQ(componentVertices, 8);
    EXPECT_EQ(componentEdges, 12);
    EXPECT_EQ(vertices, 8);
    EXPECT_EQ(vertexEdges, 24);
    EXPECT_EQ(vertexVertices, 24);
    EXPECT_EQ(vertexFaces, 24);
    EXPECT_EQ(faces, 6);
    EXPECT_EQ(faceEdges, 24);
    EXPECT_EQ(faceVertices, 24);
    EXPECT_EQ(faceFaces, 24);
    EXPECT_EQ(faceContours, 6);
    EXPECT_EQ(contourEdges, 24);
    EXPECT_EQ(contourVertices, 24);
    EXPECT_EQ(contourFaces, 24);
    EXPECT_EQ(edges, 12);
}

TEST_F(MeshApiTest, DeletingWhileWalkingTheMeshIsSafe)
{
    Cube c = cube();
    TQ3MeshIterator it;
    TQ3MeshFace f;
    int visited = 0;
    Q3ForEachMeshFace(c.mesh, f, &it)
    {
        ++visited;
        EXPECT_EQ(Q3Mesh_FaceDelete(c.mesh, f), kQ3Success);
    }
    EXPECT_EQ(visited, 6);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, c.mesh), 0u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, c.mesh), 0u);
    TQ3MeshVertex v;
    visited = 0;
    Q3ForEachMeshVertex(c.mesh, v, &it)
    {
        ++visited;
        EXPECT_EQ(Q3Mesh_VertexDelete(c.mesh, v), kQ3Success);
    }
    EXPECT_EQ(visited, 8);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, c.mesh), 0u);
}

TEST_F(MeshApiTest, IteratorsRefuseMismatchesAndPartsDeletedDuringTheWalk)
{
    Cube c = cube();
    TQ3MeshIterator it;
    ASSERT_NE(Q3Mesh_FirstMeshVertex(c.mesh, &it), nullptr);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_NextMeshFace(&it), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_NextMeshVertex(nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FirstMeshVertex(c.mesh, nullptr), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FirstMeshFace(nullptr, &it), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FirstVertexFace(nullptr, &it), nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_FirstComponentVertex(reinterpret_cast<TQ3MeshComponent>(c.v[1]), &it), nullptr),
                    kQ3ErrorInvalidParameter);

    // A face walk whose face is deleted in the middle ends with an error.
    ASSERT_NE(Q3Mesh_FirstFaceVertex(c.f[3], &it), nullptr);
    ASSERT_EQ(Q3Mesh_FaceDelete(c.mesh, c.f[3]), kQ3Success);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_NextFaceVertex(&it), nullptr), kQ3ErrorInvalidParameter);
    EXPECT_EQ(Q3Mesh_NextFaceVertex(&it), nullptr);

    // An iterator never filled in (zeros) does not match any walk.
    TQ3MeshIterator blank{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_NextContourEdge(&blank), nullptr), kQ3ErrorInvalidParameter);
}

// ---- Copies, bounds, drawing -------------------------------------------------

TEST_F(MeshApiTest, DuplicateCopiesEverythingWithNewHandlesAndSets)
{
    Cube c = cube();
    TQ3AttributeSet red = colorSet(1, 0, 0);
    EXPECT_EQ(Q3Mesh_SetFaceAttributeSet(c.mesh, c.f[0], red), kQ3Success);
    EXPECT_EQ(Q3Mesh_SetFaceAttributeSet(c.mesh, c.f[1], red), kQ3Success);
    EXPECT_EQ(Q3Mesh_SetCornerAttributeSet(c.mesh, c.v[0], c.f[0], red), kQ3Success);
    TQ3MeshIterator it;
    EXPECT_EQ(Q3Mesh_SetEdgeAttributeSet(c.mesh, Q3Mesh_FirstMeshEdge(c.mesh, &it), red), kQ3Success);
    TQ3GeometryObject copy = own(Q3Object_Duplicate(c.mesh));
    ASSERT_NE(copy, nullptr);
    EXPECT_EQ(count(Q3Mesh_GetNumVertices, copy), 8u);
    EXPECT_EQ(count(Q3Mesh_GetNumFaces, copy), 6u);
    EXPECT_EQ(count(Q3Mesh_GetNumEdges, copy), 12u);
    EXPECT_EQ(count(Q3Mesh_GetNumCorners, copy), 1u);
    TQ3MeshFace f0 = Q3Mesh_FirstMeshFace(copy, &it);
    TQ3MeshFace f1 = Q3Mesh_NextMeshFace(&it);
    ASSERT_NE(f0, c.f[0]);
    TQ3AttributeSet s0 = nullptr, s1 = nullptr, se = nullptr;
    EXPECT_EQ(Q3Mesh_GetFaceAttributeSet(copy, f0, &s0), kQ3Success);
    EXPECT_EQ(Q3Mesh_GetFaceAttributeSet(copy, f1, &s1), kQ3Success);
    EXPECT_EQ(Q3Mesh_GetEdgeAttributeSet(copy, Q3Mesh_FirstMeshEdge(copy, &it), &se), kQ3Success);
    EXPECT_NE(s0, red);
    EXPECT_EQ(s0, s1); // shared in the original, shared in the copy
    EXPECT_EQ(se, s0);
    EXPECT_EQ(expectDiffuseColor(s0).r, 1);
    Q3Object_Dispose(s0);
    Q3Object_Dispose(s1);
    Q3Object_Dispose(se);
    TQ3Point3D p{};
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Mesh_GetVertexCoordinates(copy, c.v[0], &p), kQ3Failure), kQ3ErrorInvalidParameter);
}

TEST_F(MeshApiTest, BoundsHoldTheFacesAndSubmitWorksInABoundingLoop)
{
    Cube c = cube();
    const TQ3Point3D far{10, -2, 3};
    EXPECT_EQ(Q3Mesh_SetVertexCoordinates(c.mesh, c.v[7], &far), kQ3Success);
    const TQ3BoundingBox box = boundsOf([&](TQ3ViewObject v) { EXPECT_EQ(Q3Geometry_Submit(c.mesh, v), kQ3Success); });
    EXPECT_EQ(box.isEmpty, kQ3False);
    EXPECT_FLOAT_EQ(box.min.x, 0);
    EXPECT_FLOAT_EQ(box.min.y, -2);
    EXPECT_FLOAT_EQ(box.max.x, 10);
    EXPECT_FLOAT_EQ(box.max.z, 3);
}

// The decomposition's TriMesh, read back.
struct Triangles {
    std::vector<TQ3Point3D> points;
    std::vector<unsigned long> indices;
    std::vector<TQ3ColorRGB> colors; // per point, when the TriMesh has them
};

class MeshFillTest : public MeshApiTest {
protected:
    Triangles decompose(TQ3GeometryObject mesh)
    {
        Triangles out;
        EXPECT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        TQ3GeometryObject tri = Q3Geometry_GetDecomposed(mesh, view());
        TQ3BoundingBox box;
        EXPECT_EQ(Q3View_EndBoundingBox(view(), &box), kQ3ViewStatusDone);
        EXPECT_NE(tri, nullptr);
        if (tri == nullptr)
            return out;
        EXPECT_EQ(Q3Geometry_GetType(tri), kQ3GeometryTypeTriMesh);
        TQ3TriMeshData data{};
        EXPECT_EQ(Q3TriMesh_GetData(tri, &data), kQ3Success);
        out.points.assign(data.points, data.points + data.numPoints);
        for (unsigned long t = 0; t < data.numTriangles; ++t)
            for (int k = 0; k < 3; ++k)
                out.indices.push_back(data.triangles[t].pointIndices[k]);
        for (unsigned long a = 0; a < data.numVertexAttributeTypes; ++a)
            if (data.vertexAttributeTypes[a].attributeType == kQ3AttributeTypeDiffuseColor) {
                const auto* colors = static_cast<const TQ3ColorRGB*>(data.vertexAttributeTypes[a].data);
                out.colors.assign(colors, colors + data.numPoints);
            }
        EXPECT_EQ(Q3TriMesh_EmptyData(&data), kQ3Success);
        Q3Object_Dispose(tri);
        return out;
    }
};

// How many times the triangles cover (x, y) (z = 0 everywhere here).
int coverage(const Triangles& t, double x, double y)
{
    int covered = 0;
    for (std::size_t i = 0; i < t.indices.size(); i += 3) {
        const TQ3Point3D& a = t.points[t.indices[i]];
        const TQ3Point3D& b = t.points[t.indices[i + 1]];
        const TQ3Point3D& c = t.points[t.indices[i + 2]];
        auto side = [&](const TQ3Point3D& p, const TQ3Point3D& q) {
            return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
        };
        const double s1 = side(a, b), s2 = side(b, c), s3 = side(c, a);
        covered += (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
    }
    return covered;
}

// Even-odd: inside when a ray to +x crosses the contours an odd number of
// times.
bool insideEvenOdd(const std::vector<std::vector<TQ3Point3D>>& contours, double x, double y)
{
    bool inside = false;
    for (const auto& ring : contours)
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
            const TQ3Point3D& p = ring[i];
            const TQ3Point3D& q = ring[(i + 1) % n];
            if ((p.y > y) != (q.y > y) && x < p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y))
                inside = !inside;
        }
    return inside;
}

TEST_F(MeshFillTest, AHoledFaceFillsExactlyWhereTheEvenOddRuleSays)
{
    // An outer L-shaped outline, a square hole running the same way round,
    // an island in the hole running the other way, and a triangle hole.
    const std::vector<std::vector<TQ3Point3D>> contours = {
        {{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {5, 4, 0}, {5, 10, 0}, {0, 10, 0}},
        {{1, 1, 0}, {4, 1, 0}, {4, 8, 0}, {1, 8, 0}},
        {{2, 2, 0}, {2, 5, 0}, {3, 5, 0}, {3, 2, 0}},
        {{6, 1, 0}, {9, 1, 0}, {7.5f, 3, 0}},
    };
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshFace outer = nullptr;
    for (const auto& ring : contours) {
        std::vector<TQ3MeshVertex> vertices;
        for (const TQ3Point3D& p : ring)
            vertices.push_back(vertex(mesh, p.x, p.y, p.z));
        TQ3MeshFace f = face(mesh, vertices);
        if (outer == nullptr)
            outer = f;
        else
            ASSERT_NE(Q3Mesh_FaceToContour(mesh, outer, f), nullptr);
    }
    const Triangles t = decompose(mesh);
    int inside = 0, outside = 0;
    for (int i = 0; i < 60; ++i)
        for (int j = 0; j < 60; ++j) {
            // Points off every contour line and every vertex.
            const double x = -0.5 + 11.0 * (i + 0.37) / 60.0, y = -0.5 + 11.0 * (j + 0.61) / 60.0;
            const bool expected = insideEvenOdd(contours, x, y);
            const int covered = coverage(t, x, y);
            EXPECT_EQ(covered, expected ? 1 : 0) << x << " " << y;
            (expected ? inside : outside)++;
        }
    EXPECT_GT(inside, 500);
    EXPECT_GT(outside, 500);
}

TEST_F(MeshFillTest, CornerSetsWinOverVertexSetsWhichWinOverFaceSets)
{
    TQ3GeometryObject mesh = newMesh();
    TQ3MeshVertex a = vertex(mesh, 0, 0, 0), b = vertex(mesh, 1, 0, 0, colorSet(0, 1, 0));
    TQ3MeshVertex c = vertex(mesh, 0, 1, 0, colorSet(0, 1, 0));
    TQ3MeshFace f = face(mesh, {a, b, c}, colorSet(0, 0, 1));
    EXPECT_EQ(Q3Mesh_SetCornerAttributeSet(mesh, c, f, colorSet(1, 0, 0)), kQ3Success);
    const Triangles t = decompose(mesh);
    ASSERT_EQ(t.points.size(), 3u);
    ASSERT_EQ(t.colors.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const TQ3Point3D& p = t.points[i];
        const TQ3ColorRGB& col = t.colors[i];
        if (p.x == 0 && p.y == 0)
            EXPECT_EQ(col.b, 1); // the face's blue
        else if (p.x == 1)
            EXPECT_EQ(col.g, 1); // the vertex's green
        else
            EXPECT_EQ(col.r, 1); // the corner's red
    }
}

TEST_F(MeshFillTest, TheMeshsOwnSetAndAnEmptyMeshDecomposeAsTriMeshes)
{
    TQ3GeometryObject mesh = newMesh();
    const Triangles none = decompose(mesh);
    EXPECT_TRUE(none.points.empty());
    EXPECT_TRUE(none.indices.empty());
    TQ3AttributeSet red = colorSet(1, 0, 0);
    EXPECT_EQ(Q3Geometry_SetAttributeSet(mesh, red), kQ3Success);
    TQ3AttributeSet got = nullptr;
    EXPECT_EQ(Q3Geometry_GetAttributeSet(mesh, &got), kQ3Success);
    EXPECT_EQ(got, red);
    Q3Object_Dispose(got);
    face(mesh, {vertex(mesh, 0, 0, 0), vertex(mesh, 1, 0, 0), vertex(mesh, 1, 1, 0), vertex(mesh, 0, 1, 0)});
    TQ3GeometryObject tri = own(decomposedIn(view(), mesh));
    ASSERT_NE(tri, nullptr);
    TQ3TriMeshData data{};
    ASSERT_EQ(Q3TriMesh_GetData(tri, &data), kQ3Success);
    EXPECT_EQ(data.numTriangles, 2u);
    EXPECT_EQ(data.numPoints, 4u);
    EXPECT_EQ(data.triMeshAttributeSet, red);
    EXPECT_EQ(Q3TriMesh_EmptyData(&data), kQ3Success);
}

TEST(MeshApiUninitialized, EveryFunctionFailsWithNotInitialized)
{
    ASSERT_EQ(Q3IsInitialized(), kQ3False);
    TQ3MeshIterator it{};
    unsigned long n = 0;
    TQ3Boolean b = kQ3False;
    auto failed = [] { return Q3Error_Get(nullptr) == kQ3ErrorNotInitialized; };
    EXPECT_EQ(Q3Mesh_New(), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_VertexNew(nullptr, nullptr), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FaceNew(nullptr, 0, nullptr, nullptr), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_VertexDelete(nullptr, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FaceDelete(nullptr, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_DelayUpdates(nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_ResumeUpdates(nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FaceToContour(nullptr, nullptr, nullptr), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_ContourToFace(nullptr, nullptr), nullptr);
    EXPECT_TRUE(failed());
    for (auto get : {Q3Mesh_GetNumComponents, Q3Mesh_GetNumEdges, Q3Mesh_GetNumVertices, Q3Mesh_GetNumFaces,
                     Q3Mesh_GetNumCorners}) {
        EXPECT_EQ(get(nullptr, &n), kQ3Failure);
        EXPECT_TRUE(failed());
    }
    EXPECT_EQ(Q3Mesh_GetOrientable(nullptr, &b), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetComponentNumVertices(nullptr, nullptr, &n), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetComponentNumEdges(nullptr, nullptr, &n), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3BoundingBox box;
    EXPECT_EQ(Q3Mesh_GetComponentBoundingBox(nullptr, nullptr, &box), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetComponentOrientable(nullptr, nullptr, &b), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3Point3D p{};
    EXPECT_EQ(Q3Mesh_GetVertexCoordinates(nullptr, nullptr, &p), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetVertexIndex(nullptr, nullptr, &n), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetVertexOnBoundary(nullptr, nullptr, &b), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3MeshComponent comp;
    EXPECT_EQ(Q3Mesh_GetVertexComponent(nullptr, nullptr, &comp), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3AttributeSet set;
    EXPECT_EQ(Q3Mesh_GetVertexAttributeSet(nullptr, nullptr, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_SetVertexCoordinates(nullptr, nullptr, &p), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_SetVertexAttributeSet(nullptr, nullptr, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetFaceNumVertices(nullptr, nullptr, &n), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3PlaneEquation plane;
    EXPECT_EQ(Q3Mesh_GetFacePlaneEquation(nullptr, nullptr, &plane), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetFaceNumContours(nullptr, nullptr, &n), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetFaceIndex(nullptr, nullptr, &n), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetFaceComponent(nullptr, nullptr, &comp), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetFaceAttributeSet(nullptr, nullptr, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_SetFaceAttributeSet(nullptr, nullptr, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3MeshVertex v1, v2;
    EXPECT_EQ(Q3Mesh_GetEdgeVertices(nullptr, nullptr, &v1, &v2), kQ3Failure);
    EXPECT_TRUE(failed());
    TQ3MeshFace f1, f2;
    EXPECT_EQ(Q3Mesh_GetEdgeFaces(nullptr, nullptr, &f1, &f2), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetEdgeOnBoundary(nullptr, nullptr, &b), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetEdgeComponent(nullptr, nullptr, &comp), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetEdgeAttributeSet(nullptr, nullptr, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_SetEdgeAttributeSet(nullptr, nullptr, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetContourFace(nullptr, nullptr, &f1), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetContourNumVertices(nullptr, nullptr, &n), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_GetCornerAttributeSet(nullptr, nullptr, nullptr, &set), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_SetCornerAttributeSet(nullptr, nullptr, nullptr, nullptr), kQ3Failure);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstMeshComponent(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextMeshComponent(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstComponentVertex(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextComponentVertex(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstComponentEdge(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextComponentEdge(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstMeshVertex(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextMeshVertex(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstMeshFace(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextMeshFace(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstMeshEdge(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextMeshEdge(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstVertexEdge(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextVertexEdge(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstVertexVertex(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextVertexVertex(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstVertexFace(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextVertexFace(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstFaceEdge(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextFaceEdge(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstFaceVertex(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextFaceVertex(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstFaceFace(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextFaceFace(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstFaceContour(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextFaceContour(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstContourEdge(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextContourEdge(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstContourVertex(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextContourVertex(&it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_FirstContourFace(nullptr, &it), nullptr);
    EXPECT_TRUE(failed());
    EXPECT_EQ(Q3Mesh_NextContourFace(&it), nullptr);
    EXPECT_TRUE(failed());
}

} // namespace
