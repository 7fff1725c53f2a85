// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Disk.h"

#include "geometry/DataGeometryImpl.h"

namespace q3 {

const ClassInfo kDiskClass{kQ3GeometryTypeDisk, &kGeometryClass, "disk"};

template class DataGeometry<Disk, TQ3DiskData>;

void Disk::check(const TQ3DiskData& d)
{
    checkEllipseData(d);
    requireUnitParameter(d.vMin, "vMin");
    requireUnitParameter(d.vMax, "vMax");
    requireOrdered(d.vMin, d.vMax, "vMin", "vMax");
}

std::string Disk::degeneracy(const TQ3DiskData& d)
{
    return firstCase({dependentFrame(d.majorRadius, d.minorRadius, "majorRadius and minorRadius"),
                      emptyAngle(d.uMin, d.uMax, "uMin", "uMax"), emptyRange(d.vMin, d.vMax, "vMin", "vMax")});
}

quadric::Patches Disk::patches(const TQ3DiskData& d)
{
    return quadric::diskPatches(quadric::DiskShape{toVec3(d.origin), toVec3(d.majorRadius), toVec3(d.minorRadius),
                                                   quadric::angularRange(d.uMin, d.uMax),
                                                   quadric::Range{d.vMin, d.vMax}});
}

void Disk::boundPoints(const TQ3DiskData& d, std::vector<glm::dvec3>& points)
{
    ellipseBoxCorners(toVec3(d.origin), toVec3(d.majorRadius), toVec3(d.minorRadius), points);
}

} // namespace q3
