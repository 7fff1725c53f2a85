// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The benchmarks' model of about 1 MB as an application ships one: a display
// group of eight TriMeshes with vertex normals and uvs, and quadrics with
// attribute sets and caps, as binary 3DMF bytes (modelBytes), and reading
// them back through the public path from memory (readModel).

#include "QD3D.h"
#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DIO.h"
#include "QD3DSet.h"
#include "QD3DStorage.h"
#include "QD3DView.h"

#include <cmath>
#include <vector>

namespace q3bench {

constexpr unsigned long kModelMeshes = 8;
constexpr unsigned long kModelSide = 55; // 3025 points, 5832 triangles a mesh

// A wavy grid with a normal and a uv per point (TriMesh attribute arrays).
inline TQ3GeometryObject modelMesh(unsigned long index)
{
    const unsigned long side = kModelSide;
    std::vector<TQ3Point3D> points;
    std::vector<TQ3Vector3D> normals;
    std::vector<TQ3Param2D> uvs;
    for (unsigned long y = 0; y < side; ++y)
        for (unsigned long x = 0; x < side; ++x) {
            const float u = float(x) / float(side - 1), v = float(y) / float(side - 1);
            const float height = 0.1f * std::sin(6.0f * u + float(index)) * std::cos(5.0f * v);
            points.push_back({u + float(index), v, height});
            normals.push_back({0.0f, std::sin(u) * 0.1f, 1.0f});
            uvs.push_back({u, v});
        }
    std::vector<TQ3TriMeshTriangleData> triangles;
    for (unsigned long y = 0; y + 1 < side; ++y)
        for (unsigned long x = 0; x + 1 < side; ++x) {
            const unsigned long a = y * side + x;
            triangles.push_back({{a, a + 1, a + side}});
            triangles.push_back({{a + 1, a + side + 1, a + side}});
        }
    TQ3TriMeshAttributeData vertexArrays[2] = {{kQ3AttributeTypeNormal, normals.data(), nullptr},
                                              {kQ3AttributeTypeSurfaceUV, uvs.data(), nullptr}};
    TQ3TriMeshData data{};
    data.numTriangles = triangles.size();
    data.triangles = triangles.data();
    data.numPoints = points.size();
    data.points = points.data();
    data.numVertexAttributeTypes = 2;
    data.vertexAttributeTypes = vertexArrays;
    data.bBox = {{float(index), 0, -0.1f}, {float(index) + 1, 1, 0.1f}, kQ3False};
    return Q3TriMesh_New(&data);
}

inline TQ3AttributeSet colourSet(float red)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB colour{red, 0.5f, 0.25f};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &colour);
    return set;
}

// The model's bytes: the meshes in a display group, then a few quadrics with
// attribute sets and caps at the top level.
inline std::vector<unsigned char> modelBytes()
{
    std::vector<TQ3Object> objects;
    TQ3GroupObject group = Q3DisplayGroup_New();
    for (unsigned long i = 0; i < kModelMeshes; ++i) {
        TQ3GeometryObject mesh = modelMesh(i);
        Q3Group_AddObject(group, mesh);
        Q3Object_Dispose(mesh);
    }
    objects.push_back(group);
    TQ3AttributeSet red = colourSet(1.0f), blue = colourSet(0.2f);
    for (int i = 0; i < 4; ++i) {
        const float x = float(i) * 2.5f;
        TQ3CylinderData cylinder{{x, 2, 0}, {0, 0, 1}, {0.5f, 0, 0}, {0, 0.5f, 0}, 0, 1, 0, 1,
                                 kQ3EndCapMaskTop | kQ3EndCapMaskBottom, nullptr, red, nullptr, blue, nullptr};
        objects.push_back(Q3Cylinder_New(&cylinder));
        TQ3ConeData cone{{x, 3, 0}, {0, 0, 1}, {0.5f, 0, 0}, {0, 0.5f, 0}, 0, 1, 0, 1,
                         kQ3EndCapMaskBottom, nullptr, nullptr, blue, red};
        objects.push_back(Q3Cone_New(&cone));
        TQ3TorusData torus{{x, 4, 0}, {0, 0, 0.2f}, {1, 0, 0}, {0, 1, 0}, 0.5f, 0, 1, 0, 0.75f, kQ3EndCapNone,
                           nullptr, blue};
        objects.push_back(Q3Torus_New(&torus));
        TQ3EllipsoidData ellipsoid{{x, 5, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 0, 1, 0, 1, kQ3EndCapNone,
                                   nullptr, red};
        objects.push_back(Q3Ellipsoid_New(&ellipsoid));
    }
    Q3Object_Dispose(red);
    Q3Object_Dispose(blue);
    std::vector<unsigned char> bytes;
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    TQ3FileObject file = Q3File_New();
    TQ3ViewObject view = Q3View_New();
    Q3File_SetStorage(file, storage);
    Q3File_OpenWrite(file, kQ3FileModeNormal);
    Q3View_StartWriting(view, file);
    do {
        for (TQ3Object object : objects)
            Q3Object_Submit(object, view);
    } while (Q3View_EndWriting(view) == kQ3ViewStatusRetraverse);
    Q3File_Close(file);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    Q3MemoryStorage_GetBuffer(storage, &buffer, &size, nullptr);
    bytes.assign(buffer, buffer + size);
    Q3Object_Dispose(view);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    for (TQ3Object object : objects)
        Q3Object_Dispose(object);
    return bytes;
}

// Reads every object of the bytes and disposes of them; the number read.
inline std::size_t readModel(const std::vector<unsigned char>& bytes)
{
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size()));
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    TQ3FileMode mode;
    std::size_t count = 0;
    if (Q3File_OpenRead(file, &mode) == kQ3Success) {
        while (Q3File_IsEndOfFile(file) == kQ3False) {
            TQ3Object object = Q3File_ReadObject(file);
            if (object == nullptr)
                break;
            ++count;
            Q3Object_Dispose(object);
        }
        Q3File_Close(file);
    }
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    return count;
}

/// Every object of the bytes, in order (the caller disposes of them).
inline std::vector<TQ3Object> modelObjects(const std::vector<unsigned char>& bytes)
{
    std::vector<TQ3Object> objects;
    TQ3StorageObject storage = Q3MemoryStorage_New(bytes.data(), static_cast<unsigned long>(bytes.size()));
    TQ3FileObject file = Q3File_New();
    Q3File_SetStorage(file, storage);
    TQ3FileMode mode;
    if (Q3File_OpenRead(file, &mode) == kQ3Success) {
        while (Q3File_IsEndOfFile(file) == kQ3False) {
            TQ3Object object = Q3File_ReadObject(file);
            if (object == nullptr)
                break;
            objects.push_back(object);
        }
        Q3File_Close(file);
    }
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
    return objects;
}

} // namespace q3bench
