/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */

/*
 * A 1990s-style QuickDraw 3D program (declarations first, Apple's headers by
 * their own names, every status checked) that saves what it drew with the
 * Q3 extension of Q3PixmapPNG.h, as a golden-image test does: it draws the
 * article's Listing 1 curve into a 16-bit 5-6-5 little-endian pixmap,
 * writes the draw context's image to a PNG file, reads the file back into a
 * new pixmap of the same type and compares the two byte for byte, then
 * checks that a bad call fails through the error manager. The file goes to
 * argv[1] (a scratch folder). Returns 0 when every call did what
 * Q3PixmapPNG.h promises.
 */
#include <QD3D.h>
#include <QD3DCamera.h>
#include <QD3DDrawContext.h>
#include <QD3DErrors.h>
#include <QD3DGeometry.h>
#include <QD3DRenderer.h>
#include <QD3DView.h>
#include <Q3PixmapPNG.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "LegacyCommon.h"

const char *gMyProgramName = "LegacyGolden";

#define kWidth 96
#define kHeight 64

static unsigned short gImage[kWidth * kHeight];

static TQ3ViewObject MyNewView(TQ3DrawContextObject *drawContext)
{
    TQ3ViewObject view;
    TQ3CameraObject camera;
    TQ3RendererObject renderer;

    *drawContext = MyNewPixmapDrawContext(gImage, kWidth, kHeight, 16, kQ3PixelTypeRGB16_565, kQ3EndianLittle);

    camera = MyNewOrthographicCamera(10.0f, 1.0f, 100.0f, -0.5f, 1.5f, 3.5f, -0.5f);
    renderer = Q3Renderer_NewFromType(kQ3RendererTypeWireFrame);

    view = Q3View_New();
    CHECK(Q3View_SetDrawContext(view, *drawContext));
    CHECK(Q3View_SetCamera(view, camera));
    CHECK(Q3View_SetRenderer(view, renderer));
    Q3Object_Dispose(camera);
    Q3Object_Dispose(renderer);
    return view;
}

static void MyDrawListing1(TQ3ViewObject view)
{
    static TQ3RationalPoint4D points[4] = {{0, 0, 0, 1}, {1, 1, 0, 1}, {2, 0, 0, 1}, {3, 1, 0, 1}};
    TQ3NURBCurveData curveData = MyBezierCurveData(points);
    TQ3ViewStatus status;

    CHECK(Q3View_StartRendering(view));
    do {
        CHECK(Q3NURBCurve_Submit(&curveData, view));
        status = Q3View_EndRendering(view);
    } while (status == kQ3ViewStatusRetraverse);
    Check((TQ3Boolean)(status == kQ3ViewStatusDone), "Q3View_EndRendering");
}

int main(int argc, char **argv)
{
    char path[4096];
    TQ3DrawContextObject drawContext = NULL;
    TQ3ViewObject view;
    TQ3Pixmap readBack;
    unsigned long i, white = 0;

    if (argc != 2) {
        printf("usage: LegacyGolden SCRATCHDIR\n");
        return 2;
    }
    sprintf(path, "%.4000s/legacy_golden.png", argv[1]);
    if (Q3Initialize() != kQ3Success)
        return 1;

    view = MyNewView(&drawContext);
    MyDrawListing1(view);
    CHECK(Q3PixmapDrawContext_WritePNG(drawContext, path));

    memset(&readBack, 0, sizeof readBack);
    CHECK(Q3Pixmap_ReadPNG(path, kQ3PixelTypeRGB16_565, kQ3EndianLittle, &readBack));
    Check((TQ3Boolean)(readBack.width == kWidth && readBack.height == kHeight && readBack.rowBytes == kWidth * 2 &&
                       readBack.pixelSize == 16),
          "the pixmap read back has the size written");
    Check((TQ3Boolean)(readBack.image != NULL && memcmp(readBack.image, gImage, sizeof gImage) == 0),
          "the pixmap read back has every byte drawn");
    for (i = 0; i < kWidth * kHeight; i++)
        white += gImage[i] == 0xFFFF;
    Check((TQ3Boolean)(white > 0 && white < kWidth * kHeight), "the curve (QuickDraw 3D's default white) was drawn on black");
    CHECK(Q3Pixmap_EmptyData(&readBack));
    Check((TQ3Boolean)(readBack.image == NULL), "Q3Pixmap_EmptyData sets image to NULL");

    Check((TQ3Boolean)(Q3PixmapDrawContext_WritePNG(drawContext, NULL) == kQ3Failure &&
                       Q3Error_Get(NULL) == kQ3ErrorNULLParameter),
          "Q3PixmapDrawContext_WritePNG(NULL path)");
    Check((TQ3Boolean)(Q3Pixmap_ReadPNG("/nonexistent/golden.png", kQ3PixelTypeARGB32, kQ3EndianBig, &readBack) ==
                           kQ3Failure &&
                       Q3Error_Get(NULL) == kQ3ErrorFileNotOpen && readBack.image == NULL),
          "Q3Pixmap_ReadPNG(missing file)");

    Q3Object_Dispose(view);
    Q3Object_Dispose(drawContext);
    remove(path);
    Q3Exit();
    if (gFailures == 0)
        printf("LegacyGolden: OK\n");
    return gFailures == 0 ? 0 : 1;
}
