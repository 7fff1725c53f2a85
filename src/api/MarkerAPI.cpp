// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/GeometryEntry.h"
#include "geometry/Marker.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Marker_New(const TQ3MarkerData* markerData)
{
    return newGeometry<Marker>(__func__, markerData);
}

TQ3Status Q3Marker_Submit(const TQ3MarkerData* markerData, TQ3ViewObject view)
{
    return submitGeometry<Marker>(__func__, markerData, view);
}

TQ3Status Q3Marker_SetData(TQ3GeometryObject geometry, const TQ3MarkerData* markerData)
{
    return setGeometryData<Marker>(__func__, geometry, markerData);
}

TQ3Status Q3Marker_GetData(TQ3GeometryObject geometry, TQ3MarkerData* markerData)
{
    return getGeometryData<Marker>(__func__, geometry, markerData);
}

TQ3Status Q3Marker_EmptyData(TQ3MarkerData* markerData)
{
    return emptyGeometryData<Marker>(__func__, markerData);
}

TQ3Status Q3Marker_GetPosition(TQ3GeometryObject marker, TQ3Point3D* location)
{
    return getValue<Marker>(__func__, marker, "marker", location, "location",
                            [](const Marker& m) { return m.data().location; });
}

TQ3Status Q3Marker_SetPosition(TQ3GeometryObject marker, const TQ3Point3D* location)
{
    return setValue<Marker>(__func__, marker, "marker", location, "location", &Marker::setPosition);
}

TQ3Status Q3Marker_GetXOffset(TQ3GeometryObject marker, long* xOffset)
{
    return getValue<Marker>(__func__, marker, "marker", xOffset, "xOffset",
                            [](const Marker& m) { return m.data().xOffset; });
}

TQ3Status Q3Marker_SetXOffset(TQ3GeometryObject marker, long xOffset)
{
    return guardStatus(__func__, [&] { lookup<Marker>(marker, "marker").setXOffset(xOffset); });
}

TQ3Status Q3Marker_GetYOffset(TQ3GeometryObject marker, long* yOffset)
{
    return getValue<Marker>(__func__, marker, "marker", yOffset, "yOffset",
                            [](const Marker& m) { return m.data().yOffset; });
}

TQ3Status Q3Marker_SetYOffset(TQ3GeometryObject marker, long yOffset)
{
    return guardStatus(__func__, [&] { lookup<Marker>(marker, "marker").setYOffset(yOffset); });
}

TQ3Status Q3Marker_GetBitmap(TQ3GeometryObject marker, TQ3Bitmap* bitmap)
{
    return guardStatus(__func__, [&] {
        const Marker& source = lookup<Marker>(marker, "marker");
        requireNonNull(bitmap, "bitmap");
        source.copyBitmap(*bitmap);
    });
}

TQ3Status Q3Marker_SetBitmap(TQ3GeometryObject marker, const TQ3Bitmap* bitmap)
{
    return setValue<Marker>(__func__, marker, "marker", bitmap, "bitmap", &Marker::setBitmap);
}

} // extern "C"
