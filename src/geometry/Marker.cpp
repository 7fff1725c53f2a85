// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Marker.h"

#include "core/EnumValue.h"
#include "geometry/DataGeometryImpl.h"

#include <cstdlib>
#include <cstring>

namespace q3 {

const ClassInfo kMarkerClass{kQ3GeometryTypeMarker, &kGeometryClass, "marker"};

template class DataGeometry<Marker, TQ3MarkerData>;

void Marker::checkBitmap(const TQ3Bitmap& bitmap)
{
    layout::checkStructure(bitmap, layout::Path{nullptr, "bitmap"});
    checkBitmapRules(bitmap);
}

void Marker::checkBitmapRules(const TQ3Bitmap& bitmap)
{
    if (bitmap.width == 0 || bitmap.height == 0)
        fail(kQ3ErrorInvalidData, "the bitmap is " + std::to_string(bitmap.width) + " x " +
                                      std::to_string(bitmap.height) + " pixels; a marker needs at least one");
    if (bitmap.rowBytes < bitmap.width / 8 + (bitmap.width % 8 != 0 ? 1 : 0))
        fail(kQ3ErrorInvalidData, "bitmap.rowBytes " + std::to_string(bitmap.rowBytes) + " cannot hold " +
                                      std::to_string(bitmap.width) + " pixels");
    const long order = enumValue(bitmap.bitOrder);
    if (order != kQ3EndianBig && order != kQ3EndianLittle)
        fail(kQ3ErrorInvalidData, "bitmap.bitOrder " + std::to_string(order) + " is not a TQ3Endian");
}

void Marker::check(const TQ3MarkerData& data)
{
    checkBitmapRules(data.bitmap);
}

void Marker::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    const TQ3MarkerData& d = data();
    ScreenBitmap bitmap;
    bitmap.xOffset = d.xOffset;
    bitmap.yOffset = d.yOffset;
    bitmap.width = std::uint32_t(d.bitmap.width);
    bitmap.height = std::uint32_t(d.bitmap.height);
    bitmap.rowBytes = d.bitmap.rowBytes;
    bitmap.bits = d.bitmap.image;
    bitmap.lsbFirst = enumValue(d.bitmap.bitOrder) == kQ3EndianLittle;
    MeshView mesh;
    mesh.bitmaps = &bitmap;
    mesh.bitmapCount = 1;
    drawAt(d.location, mesh, sink);
}

void Marker::setPosition(const TQ3Point3D& location)
{
    requireFinite(location, "location");
    editableData().location = location;
    markEdited();
}

void Marker::setXOffset(long xOffset)
{
    editableData().xOffset = xOffset;
    markEdited();
}

void Marker::setYOffset(long yOffset)
{
    editableData().yOffset = yOffset;
    markEdited();
}

void Marker::copyBitmap(TQ3Bitmap& out) const
{
    TQ3Bitmap copy = data().bitmap;
    const std::size_t bytes = std::size_t(copy.rowBytes) * copy.height;
    copy.image = layout::allocate<unsigned char>(bytes);
    std::memcpy(copy.image, data().bitmap.image, bytes);
    out = copy;
}

void Marker::setBitmap(const TQ3Bitmap& bitmap)
{
    checkBitmap(bitmap);
    TQ3Bitmap copy = bitmap;
    const std::size_t bytes = std::size_t(copy.rowBytes) * copy.height;
    copy.image = layout::allocate<unsigned char>(bytes);
    std::memcpy(copy.image, bitmap.image, bytes);
    std::free(editableData().bitmap.image);
    editableData().bitmap = copy;
    markEdited();
}

} // namespace q3
