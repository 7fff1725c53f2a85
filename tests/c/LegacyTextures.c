/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * Legacy code for QuickDraw 3D 1.6's textures, written the way 1990s
 * Macintosh games loaded theirs (declarations first, Apple's headers by
 * their own names, every status checked), built with nothing but
 * -I include/Q3: it must compile unmodified against Q3. It fills a 2 x 2
 * pixmap in a memory storage, makes a pixmap texture, a mipmap texture and
 * texture shaders from them, uses the colour routines, and draws a
 * textured TriMesh into a pixmap, checking that each quarter of the square
 * shows its texel. Returns 0 when every call did what the 1.6 API promises.
 */
#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DMath.h>
#include <QD3DRenderer.h>
#include <QD3DSet.h>
#include <QD3DShader.h>
#include <QD3DStorage.h>
#include <QD3DView.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "LegacyTextures";

/* Texels, ARGB32 big-endian, top row first: red, green / blue, white. */
static unsigned char gTexels[16] = {0xFF, 0xFF, 0, 0, 0xFF, 0, 0xFF, 0,
                                    0xFF, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};

static void MyColors(void)
{
    TQ3ColorRGB a, b, sum;
    TQ3ColorARGB argb;
    float luminance;

    Q3ColorRGB_Set(&a, 0.5f, 0.25f, 2.0f);
    Q3ColorRGB_Set(&b, 0.5f, 0.25f, -1.0f);
    Check((TQ3Boolean)(Q3ColorRGB_Add(&a, &b, &sum) == &sum && sum.r == 1.0f && sum.b == 1.0f), "Q3ColorRGB_Add");
    Check((TQ3Boolean)(Q3ColorRGB_Clamp(&a, &a) == &a && a.b == 1.0f), "Q3ColorRGB_Clamp");
    Check((TQ3Boolean)(Q3ColorRGB_Luminance(Q3ColorRGB_Scale(&b, 0.0f, &b), &luminance) == &luminance &&
                       luminance == 0.0f),
          "Q3ColorRGB_Luminance");
    Check((TQ3Boolean)(Q3ColorARGB_Set(&argb, 1.0f, 0.0f, 0.0f, 0.0f) == &argb && argb.a == 1.0f), "Q3ColorARGB_Set");
    Check((TQ3Boolean)(Q3ColorRGB_Set(NULL, 0, 0, 0) == NULL && Q3Error_Get(NULL) == kQ3ErrorNULLParameter),
          "Q3ColorRGB_Set(NULL)");
}

static TQ3TextureObject MyNewMipmapTexture(TQ3StorageObject storage)
{
    TQ3Mipmap mipmap;

    memset(&mipmap, 0, sizeof mipmap);
    mipmap.image = storage;
    mipmap.useMipmapping = kQ3False;
    mipmap.pixelType = kQ3PixelTypeARGB32;
    mipmap.bitOrder = kQ3EndianBig;
    mipmap.byteOrder = kQ3EndianBig;
    mipmap.reserved = 0;
    mipmap.mipmaps[0].width = 2;
    mipmap.mipmaps[0].height = 2;
    mipmap.mipmaps[0].rowBytes = 8;
    mipmap.mipmaps[0].offset = 0;
    return Q3MipmapTexture_New(&mipmap);
}

/* A unit square at z = 0 with its corners' surface uv. */
static TQ3GeometryObject MyNewSquare(void)
{
    TQ3TriMeshData data;
    TQ3Point3D points[4];
    TQ3Param2D uvs[4];
    TQ3TriMeshTriangleData triangles[2];
    TQ3TriMeshAttributeData uvArray;

    Q3Point3D_Set(&points[0], -1.0f, -1.0f, 0.0f);
    Q3Point3D_Set(&points[1], 1.0f, -1.0f, 0.0f);
    Q3Point3D_Set(&points[2], 1.0f, 1.0f, 0.0f);
    Q3Point3D_Set(&points[3], -1.0f, 1.0f, 0.0f);
    Q3Param2D_Set(&uvs[0], 0.0f, 0.0f);
    Q3Param2D_Set(&uvs[1], 1.0f, 0.0f);
    Q3Param2D_Set(&uvs[2], 1.0f, 1.0f);
    Q3Param2D_Set(&uvs[3], 0.0f, 1.0f);
    triangles[0].pointIndices[0] = 0;
    triangles[0].pointIndices[1] = 1;
    triangles[0].pointIndices[2] = 2;
    triangles[1].pointIndices[0] = 0;
    triangles[1].pointIndices[1] = 2;
    triangles[1].pointIndices[2] = 3;
    uvArray.attributeType = kQ3AttributeTypeSurfaceUV;
    uvArray.data = uvs;
    uvArray.attributeUseArray = NULL;
    memset(&data, 0, sizeof data);
    data.numTriangles = 2;
    data.triangles = triangles;
    data.numPoints = 4;
    data.points = points;
    data.numVertexAttributeTypes = 1;
    data.vertexAttributeTypes = &uvArray;
    Q3BoundingBox_SetFromPoints3D(&data.bBox, points, 4, sizeof(TQ3Point3D));
    return Q3TriMesh_New(&data);
}

/* Draws the square under the shader into a 32 x 32 ARGB32 pixmap, the
 * square filling its middle 16 x 16, and checks the four quarters. */
static void MyDraw(TQ3ShaderObject shader, TQ3GeometryObject square)
{
    TQ3DrawContextObject context;
    TQ3CameraObject camera;
    TQ3ViewObject view;
    unsigned char *pixels, *p;
    static const int kQuarters[4][2] = {{12, 12}, {19, 12}, {12, 19}, {19, 19}};
    int i;

    pixels = (unsigned char *)calloc(32 * 32, 4);
    view = Q3View_New();
    context = MyNewARGBDrawContext(pixels, 32, 32);
    camera = MyNewOrthographicCamera(5.0f, 0.5f, 20.0f, -2.0f, 2.0f, 2.0f, -2.0f);
    if (pixels == NULL || view == NULL || context == NULL || camera == NULL) {
        gFailures++;
        return;
    }
    CHECK(Q3View_SetDrawContext(view, context));
    CHECK(Q3View_SetCamera(view, camera));
    CHECK(Q3View_SetRendererByType(view, kQ3RendererTypeInteractive));
    CHECK(Q3View_StartRendering(view));
    do {
        CHECK(Q3Shader_Submit(shader, view));
        CHECK(Q3Geometry_Submit(square, view));
    } while (Q3View_EndRendering(view) == kQ3ViewStatusRetraverse);
    /* The image's top row is the texture's top row. */
    for (i = 0; i < 4; i++) {
        p = pixels + 4 * (kQuarters[i][1] * 32 + kQuarters[i][0]);
        Check((TQ3Boolean)(memcmp(p + 1, gTexels + 4 * i + 1, 3) == 0), "a quarter's texel");
    }
    Q3Object_Dispose(camera);
    Q3Object_Dispose(context);
    Q3Object_Dispose(view);
    free(pixels);
}

int main(void)
{
    TQ3StorageObject storage;
    TQ3StoragePixmap pixmap;
    TQ3TextureObject texture, mipmapTexture, got;
    TQ3ShaderObject shader;
    TQ3GeometryObject square;
    unsigned long width = 0, height = 0;

    if (Q3Initialize() != kQ3Success)
        return 1;
    MyColors();
    storage = Q3MemoryStorage_New(gTexels, sizeof gTexels);
    if (storage == NULL)
        return 2;
    pixmap.image = storage;
    pixmap.width = 2;
    pixmap.height = 2;
    pixmap.rowBytes = 8;
    pixmap.pixelSize = 32;
    pixmap.pixelType = kQ3PixelTypeARGB32;
    pixmap.bitOrder = kQ3EndianBig;
    pixmap.byteOrder = kQ3EndianBig;
    texture = Q3PixmapTexture_New(&pixmap);
    mipmapTexture = MyNewMipmapTexture(storage);
    square = MyNewSquare();
    if (texture == NULL || mipmapTexture == NULL || square == NULL)
        return 3;
    Check((TQ3Boolean)(Q3Texture_GetType(texture) == kQ3TextureTypePixmap), "Q3Texture_GetType");
    CHECK(Q3Texture_GetWidth(mipmapTexture, &width));
    CHECK(Q3Texture_GetHeight(mipmapTexture, &height));
    Check((TQ3Boolean)(width == 2 && height == 2), "the mipmap's size");
    CHECK(Q3PixmapTexture_GetPixmap(texture, &pixmap));
    Check((TQ3Boolean)(pixmap.image == storage), "the pixmap's storage");
    Q3Object_Dispose(pixmap.image);
    CHECK(Q3PixmapTexture_SetPixmap(texture, &pixmap));

    shader = Q3TextureShader_New(texture);
    if (shader == NULL)
        return 4;
    Check((TQ3Boolean)(Q3Shader_GetType(shader) == kQ3ShaderTypeSurface), "Q3Shader_GetType");
    Check((TQ3Boolean)(Q3SurfaceShader_GetType(shader) == kQ3SurfaceShaderTypeTexture), "Q3SurfaceShader_GetType");
    MyDraw(shader, square);
    CHECK(Q3TextureShader_SetTexture(shader, mipmapTexture));
    CHECK(Q3TextureShader_GetTexture(shader, &got));
    Check((TQ3Boolean)(got == mipmapTexture), "Q3TextureShader_GetTexture");
    Q3Object_Dispose(got);
    MyDraw(shader, square);

    Q3Object_Dispose(shader);
    Q3Object_Dispose(square);
    Q3Object_Dispose(mipmapTexture);
    Q3Object_Dispose(texture);
    Q3Object_Dispose(storage);
    if (Q3Exit() != kQ3Success)
        return 5;
    return gFailures == 0 ? 0 : 10;
}
