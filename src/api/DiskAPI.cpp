// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DGeometry.h"
#include "api/QuadricEntry.h"
#include "geometry/Disk.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3GeometryObject Q3Disk_New(const TQ3DiskData* diskData)
{
    return newGeometry<Disk>(__func__, diskData);
}

TQ3Status Q3Disk_Submit(const TQ3DiskData* diskData, TQ3ViewObject view)
{
    return submitGeometry<Disk>(__func__, diskData, view);
}

TQ3Status Q3Disk_SetData(TQ3GeometryObject disk, const TQ3DiskData* diskData)
{
    return setGeometryData<Disk>(__func__, disk, diskData);
}

TQ3Status Q3Disk_GetData(TQ3GeometryObject disk, TQ3DiskData* diskData)
{
    return getGeometryData<Disk>(__func__, disk, diskData);
}

TQ3Status Q3Disk_EmptyData(TQ3DiskData* diskData)
{
    return emptyGeometryData<Disk>(__func__, diskData);
}

TQ3Status Q3Disk_SetOrigin(TQ3GeometryObject disk, const TQ3Point3D* origin)
{
    return setField<Disk>(__func__, disk, &TQ3DiskData::origin, origin, "origin");
}

TQ3Status Q3Disk_GetOrigin(TQ3GeometryObject disk, TQ3Point3D* origin)
{
    return getField<Disk>(__func__, disk, &TQ3DiskData::origin, origin, "origin");
}

TQ3Status Q3Disk_SetMajorRadius(TQ3GeometryObject disk, const TQ3Vector3D* majorRadius)
{
    return setField<Disk>(__func__, disk, &TQ3DiskData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Disk_GetMajorRadius(TQ3GeometryObject disk, TQ3Vector3D* majorRadius)
{
    return getField<Disk>(__func__, disk, &TQ3DiskData::majorRadius, majorRadius, "majorRadius");
}

TQ3Status Q3Disk_SetMinorRadius(TQ3GeometryObject disk, const TQ3Vector3D* minorRadius)
{
    return setField<Disk>(__func__, disk, &TQ3DiskData::minorRadius, minorRadius, "minorRadius");
}

TQ3Status Q3Disk_GetMinorRadius(TQ3GeometryObject disk, TQ3Vector3D* minorRadius)
{
    return getField<Disk>(__func__, disk, &TQ3DiskData::minorRadius, minorRadius, "minorRadius");
}

} // extern "C"
