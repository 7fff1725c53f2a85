// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/PixmapMarker.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3PixmapMarker_New(const TQ3PixmapMarkerData* pixmapMarkerData)
{
    return newGeometry<PixmapMarker>(__func__, pixmapMarkerData);
}

TQ3Status Q3PixmapMarker_Submit(const TQ3PixmapMarkerData* pixmapMarkerData, TQ3ViewObject view)
{
    return submitGeometry<PixmapMarker>(__func__, pixmapMarkerData, view);
}

TQ3Status Q3PixmapMarker_SetData(TQ3GeometryObject geometry, const TQ3PixmapMarkerData* pixmapMarkerData)
{
    return setGeometryData<PixmapMarker>(__func__, geometry, pixmapMarkerData);
}

TQ3Status Q3PixmapMarker_GetData(TQ3GeometryObject geometry, TQ3PixmapMarkerData* pixmapMarkerData)
{
    return getGeometryData<PixmapMarker>(__func__, geometry, pixmapMarkerData);
}

TQ3Status Q3PixmapMarker_EmptyData(TQ3PixmapMarkerData* pixmapMarkerData)
{
    return emptyGeometryData<PixmapMarker>(__func__, pixmapMarkerData);
}

TQ3Status Q3PixmapMarker_GetPosition(TQ3GeometryObject pixmapMarker, TQ3Point3D* position)
{
    return getValue<PixmapMarker>(__func__, pixmapMarker, "pixmapMarker", position, "position",
                                  [](const PixmapMarker& m) { return m.data().position; });
}

TQ3Status Q3PixmapMarker_SetPosition(TQ3GeometryObject pixmapMarker, const TQ3Point3D* position)
{
    return setValue<PixmapMarker>(__func__, pixmapMarker, "pixmapMarker", position, "position",
                                  &PixmapMarker::setPosition);
}

TQ3Status Q3PixmapMarker_GetXOffset(TQ3GeometryObject pixmapMarker, long* xOffset)
{
    return getValue<PixmapMarker>(__func__, pixmapMarker, "pixmapMarker", xOffset, "xOffset",
                                  [](const PixmapMarker& m) { return m.data().xOffset; });
}

TQ3Status Q3PixmapMarker_SetXOffset(TQ3GeometryObject pixmapMarker, long xOffset)
{
    return guardStatus(__func__, [&] { lookup<PixmapMarker>(pixmapMarker, "pixmapMarker").setXOffset(xOffset); });
}

TQ3Status Q3PixmapMarker_GetYOffset(TQ3GeometryObject pixmapMarker, long* yOffset)
{
    return getValue<PixmapMarker>(__func__, pixmapMarker, "pixmapMarker", yOffset, "yOffset",
                                  [](const PixmapMarker& m) { return m.data().yOffset; });
}

TQ3Status Q3PixmapMarker_SetYOffset(TQ3GeometryObject pixmapMarker, long yOffset)
{
    return guardStatus(__func__, [&] { lookup<PixmapMarker>(pixmapMarker, "pixmapMarker").setYOffset(yOffset); });
}

TQ3Status Q3PixmapMarker_GetPixmap(TQ3GeometryObject pixmapMarker, TQ3StoragePixmap* pixmap)
{
    return guardStatus(__func__, [&] {
        const PixmapMarker& source = lookup<PixmapMarker>(pixmapMarker, "pixmapMarker");
        requireNonNull(pixmap, "pixmap");
        source.copyPixmap(*pixmap);
    });
}

TQ3Status Q3PixmapMarker_SetPixmap(TQ3GeometryObject pixmapMarker, const TQ3StoragePixmap* pixmap)
{
    return setValue<PixmapMarker>(__func__, pixmapMarker, "pixmapMarker", pixmap, "pixmap", &PixmapMarker::setPixmap);
}

} // extern "C"
