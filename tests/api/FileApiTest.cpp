// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "FileTestSupport.h"
#include "Q3ApiTest.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DSet.h"

#include <cstring>

using namespace q3test;

namespace {

class FileApiTest : public Q3ApiTest {};

const TQ3FileMode kModes[] = {kQ3FileModeNormal, kQ3FileModeNormal | kQ3FileModeText, kQ3FileModeStream,
                              kQ3FileModeStream | kQ3FileModeText};

TQ3AttributeSet colorSet(float r, float g, float b)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    const TQ3ColorRGB color = {r, g, b};
    Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &color);
    return set;
}

} // namespace

TEST_F(FileApiTest, FileObjectStateAndErrors)
{
    TQ3FileObject file = Q3File_New();
    ASSERT_NE(file, nullptr);
    TQ3Boolean open = kQ3True;
    ASSERT_EQ(Q3File_IsOpen(file, &open), kQ3Success);
    EXPECT_EQ(open, kQ3False);
    TQ3FileMode mode = 0;
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_OpenRead(file, &mode), kQ3Failure), kQ3ErrorNoStorageSetForFile);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_GetMode(file, &mode), kQ3Failure), kQ3ErrorFileNotOpen);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_Close(file), kQ3Failure), kQ3ErrorFileNotOpen);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorFileNotOpen);
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);

    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    ASSERT_EQ(Q3File_SetStorage(file, storage), kQ3Success);
    TQ3StorageObject got = nullptr;
    ASSERT_EQ(Q3File_GetStorage(file, &got), kQ3Success);
    EXPECT_EQ(got, storage);
    Q3Object_Dispose(got);
    EXPECT_Q3_ERROR(Q3File_OpenWrite(file, 16), kQ3ErrorInvalidParameter);
    EXPECT_Q3_ERROR(Q3File_OpenWrite(file, kQ3FileModeStream | kQ3FileModeDatabase), kQ3ErrorInvalidParameter);
    ASSERT_EQ(Q3File_OpenWrite(file, kQ3FileModeText), kQ3Success);
    EXPECT_Q3_ERROR(Q3File_OpenWrite(file, kQ3FileModeText), kQ3ErrorFileAlreadyOpen);
    EXPECT_Q3_ERROR(Q3File_SetStorage(file, nullptr), kQ3ErrorFileIsOpen);
    EXPECT_Q3_ERROR(Q3MemoryStorage_Set(storage, nullptr, 0), kQ3ErrorStorageInUse);
    ASSERT_EQ(Q3File_GetMode(file, &mode), kQ3Success);
    EXPECT_EQ(mode, static_cast<TQ3FileMode>(kQ3FileModeText));
    TQ3FileVersion version = 0;
    ASSERT_EQ(Q3File_GetVersion(file, &version), kQ3Success);
    EXPECT_EQ(version, kQ3FileVersionCurrent);
    ASSERT_EQ(Q3File_Close(file), kQ3Success);

    // An empty text file: a header only.
    unsigned long size = 0;
    Q3Storage_GetSize(storage, &size);
    EXPECT_GT(size, 0u);
    ASSERT_EQ(Q3File_OpenRead(file, &mode), kQ3Success);
    EXPECT_EQ(mode, static_cast<TQ3FileMode>(kQ3FileModeText));
    EXPECT_EQ(Q3File_IsEndOfFile(file), kQ3True);
    EXPECT_EQ(Q3File_GetNextObjectType(file), kQ3ObjectTypeInvalid);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3File_ReadObject(file), nullptr), kQ3ErrorEndOfFile);
    ASSERT_EQ(Q3File_Cancel(file), kQ3Success);
    Q3Object_Dispose(file);
    Q3Object_Dispose(storage);
}

TEST_F(FileApiTest, WritingLoopErrors)
{
    TQ3ViewObject view = Q3View_New();
    TQ3FileObject file = Q3File_New();
    EXPECT_Q3_ERROR(Q3View_StartWriting(view, file), kQ3ErrorFileNotOpen);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_EndWriting(view), kQ3ViewStatusError), kQ3ErrorWriteStateInactive);
    TQ3StorageObject storage = Q3MemoryStorage_New(nullptr, 0);
    Q3File_SetStorage(file, storage);
    Q3File_OpenWrite(file, kQ3FileModeNormal);
    ASSERT_EQ(Q3View_StartWriting(view, file), kQ3Success);
    EXPECT_Q3_ERROR(Q3View_StartWriting(view, file), kQ3ErrorViewIsStarted);
    EXPECT_Q3_ERROR(Q3Object_Submit(view, view), kQ3ErrorInvalidObjectType);
    EXPECT_EQ(Q3View_EndWriting(view), kQ3ViewStatusDone);
    Q3File_Close(file);
    Q3Object_Dispose(storage);
    Q3Object_Dispose(file);
    Q3Object_Dispose(view);
}

TEST_F(FileApiTest, TrianglesWithAttributeSetsRoundTripInEveryMode)
{
    TQ3AttributeSet own = colorSet(1, 0, 0);
    TQ3AttributeSet corner = Q3AttributeSet_New();
    const TQ3Vector3D normal = {0, 0, 1};
    const TQ3Param2D uv = {0.25f, 0.75f};
    const float ambient = 0.5f;
    const TQ3ColorRGB specular = {0.1f, 0.2f, 0.3f};
    const TQ3Switch highlight = kQ3On;
    Q3AttributeSet_Add(corner, kQ3AttributeTypeNormal, &normal);
    Q3AttributeSet_Add(corner, kQ3AttributeTypeSurfaceUV, &uv);
    Q3AttributeSet_Add(corner, kQ3AttributeTypeAmbientCoefficient, &ambient);
    Q3AttributeSet_Add(corner, kQ3AttributeTypeSpecularColor, &specular);
    Q3AttributeSet_Add(corner, kQ3AttributeTypeHighlightState, &highlight);
    TQ3TriangleData data = {{{{0, 0, 0}, nullptr}, {{1.5f, 0, 0}, corner}, {{0, 1e-7f, -3}, nullptr}}, own};
    TQ3GeometryObject triangle = Q3Triangle_New(&data);
    for (TQ3FileMode mode : kModes) {
        SCOPED_TRACE(mode);
        const auto bytes = writeObjects({triangle}, mode);
        const auto objects = readAll(bytes);
        ASSERT_EQ(objects.size(), 1u);
        ASSERT_EQ(Q3Object_GetLeafType(objects[0]), kQ3GeometryTypeTriangle);
        TQ3TriangleData back;
        ASSERT_EQ(Q3Triangle_GetData(objects[0], &back), kQ3Success);
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(back.vertices[i].point.x, data.vertices[i].point.x);
            EXPECT_EQ(back.vertices[i].point.y, data.vertices[i].point.y);
            EXPECT_EQ(back.vertices[i].point.z, data.vertices[i].point.z);
            EXPECT_EQ(back.vertices[i].attributeSet != nullptr, data.vertices[i].attributeSet != nullptr);
        }
        TQ3ColorRGB color = {};
        ASSERT_EQ(Q3AttributeSet_Get(back.triangleAttributeSet, kQ3AttributeTypeDiffuseColor, &color), kQ3Success);
        EXPECT_EQ(color.r, 1.0f);
        TQ3Vector3D n = {};
        TQ3Param2D p = {};
        float a = 0;
        TQ3ColorRGB s = {};
        TQ3Switch h = kQ3Off;
        ASSERT_EQ(Q3AttributeSet_Get(back.vertices[1].attributeSet, kQ3AttributeTypeNormal, &n), kQ3Success);
        ASSERT_EQ(Q3AttributeSet_Get(back.vertices[1].attributeSet, kQ3AttributeTypeSurfaceUV, &p), kQ3Success);
        ASSERT_EQ(Q3AttributeSet_Get(back.vertices[1].attributeSet, kQ3AttributeTypeAmbientCoefficient, &a),
                  kQ3Success);
        ASSERT_EQ(Q3AttributeSet_Get(back.vertices[1].attributeSet, kQ3AttributeTypeSpecularColor, &s), kQ3Success);
        ASSERT_EQ(Q3AttributeSet_Get(back.vertices[1].attributeSet, kQ3AttributeTypeHighlightState, &h),
                  kQ3Success);
        EXPECT_EQ(n.z, 1.0f);
        EXPECT_EQ(p.u, 0.25f);
        EXPECT_EQ(p.v, 0.75f);
        EXPECT_EQ(a, 0.5f);
        EXPECT_EQ(s.g, 0.2f);
        EXPECT_EQ(h, kQ3On);
        Q3Triangle_EmptyData(&back);
        disposeAll(objects);
    }
    Q3Object_Dispose(triangle);
    Q3Object_Dispose(corner);
    Q3Object_Dispose(own);
}

TEST_F(FileApiTest, AGroupNestedPastTheLimitIsNotWrittenAndLeavesTheFileWhole)
{
    // 300 display groups, each inside the next: deeper than a file may nest.
    TQ3GroupObject inner = Q3DisplayGroup_New();
    TQ3PointData pointData = {{1, 2, 3}, nullptr};
    TQ3GeometryObject point = Q3Point_New(&pointData);
    Q3Group_AddObject(inner, point);
    for (int i = 0; i < 300; ++i) {
        TQ3GroupObject outer = Q3DisplayGroup_New();
        Q3Group_AddObject(outer, inner);
        Q3Object_Dispose(inner);
        inner = outer;
    }
    const auto objects = readAll(writeFileWith(kQ3FileModeNormal, [&](TQ3ViewObject view) {
        EXPECT_EQ(Q3Object_Submit(point, view), kQ3Success);
        EXPECT_Q3_ERROR(EXPECT_EQ(Q3Object_Submit(inner, view), kQ3Failure), kQ3ErrorInvalidMetafile);
        EXPECT_EQ(Q3Object_Submit(point, view), kQ3Success); // a reference to the first
    }));
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(objects[0], objects[1]); // the reference gives the same point
    disposeAll(objects);
    Q3Object_Dispose(inner);
    Q3Object_Dispose(point);
}
