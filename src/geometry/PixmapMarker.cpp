// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/PixmapMarker.h"

#include "core/EnumValue.h"
#include "core/PixelFormat.h"
#include "geometry/DataGeometryImpl.h"
// The storage interface depends only on core; the pixmap marker is the one
// geometry whose data lives in a storage object (QD3DStorage.h).
#include "base/Storage.h"

#include <string>
#include <utility>
#include <vector>

namespace q3 {

const ClassInfo kPixmapMarkerClass{kQ3GeometryTypePixmapMarker, &kGeometryClass, "pixmap marker"};

template class DataGeometry<PixmapMarker, TQ3PixmapMarkerData>;

namespace {

std::size_t imageBytes(const TQ3StoragePixmap& pixmap)
{
    return layout::countProduct(&TQ3StoragePixmap::rowBytes, &TQ3StoragePixmap::height)(pixmap);
}

} // namespace

void PixmapMarker::checkPixmap(const TQ3StoragePixmap& pixmap)
{
    layout::checkStructure(pixmap, layout::Path{nullptr, "pixmap"});
    checkPixmapRules(pixmap);
}

void PixmapMarker::checkPixmapRules(const TQ3StoragePixmap& pixmap)
{
    const long type = enumValue(pixmap.pixelType);
    const unsigned long bits = bitsPerPixel(type);
    if (bits == 0)
        fail(kQ3ErrorInvalidData, "pixmap.pixelType " + std::to_string(type) + " is not a TQ3PixelType");
    if (!isEndian(enumValue(pixmap.byteOrder)))
        fail(kQ3ErrorInvalidData,
             "pixmap.byteOrder " + std::to_string(enumValue(pixmap.byteOrder)) + " is not a TQ3Endian");
    if (!isEndian(enumValue(pixmap.bitOrder)))
        fail(kQ3ErrorInvalidData,
             "pixmap.bitOrder " + std::to_string(enumValue(pixmap.bitOrder)) + " is not a TQ3Endian");
    if (pixmap.pixelSize != bits)
        fail(kQ3ErrorUnsupportedPixelDepth, "pixmap.pixelSize " + std::to_string(pixmap.pixelSize) +
                                                " is not the " + std::to_string(bits) +
                                                " bits of its pixel type");
    if (pixmap.width == 0 || pixmap.height == 0)
        fail(kQ3ErrorInvalidData, "the pixmap is " + std::to_string(pixmap.width) + " x " +
                                      std::to_string(pixmap.height) + " pixels; a pixmap marker needs at least one");
    // width * bytes per pixel cannot overflow a rowBytes that holds it: compare
    // by division.
    const unsigned long bytesPerPixel = bits / 8;
    if (pixmap.rowBytes / bytesPerPixel < pixmap.width)
        fail(kQ3ErrorInvalidData, "pixmap.rowBytes " + std::to_string(pixmap.rowBytes) + " cannot hold " +
                                      std::to_string(pixmap.width) + " pixels of " + std::to_string(bits) +
                                      " bits");
    const std::size_t bytes = imageBytes(pixmap);
    layout::checkCount(bytes, layout::Path{nullptr, "pixmap.image"});
    const Storage& storage = lookup<Storage>(pixmap.image, "pixmap.image");
    const std::size_t held = storage.size();
    if (held < bytes)
        fail(kQ3ErrorInvalidData, "the pixmap's storage holds " + std::to_string(held) + " bytes, fewer than the " +
                                      std::to_string(bytes) + " of rowBytes * height");
}

void PixmapMarker::check(const TQ3PixmapMarkerData& data)
{
    checkPixmapRules(data.pixmap);
}

void PixmapMarker::decompose(const DecomposeContext&, PrimitiveSink& sink) const
{
    const TQ3PixmapMarkerData& d = data();
    const std::size_t bytes = imageBytes(d.pixmap);
    std::vector<unsigned char> pixels(bytes);
    const Storage& storage = *static_cast<const Storage*>(layout::heldObject(d.pixmap.image));
    const std::size_t read = storage.read(0, bytes, pixels.data());
    if (read < bytes)
        fail(kQ3ErrorInvalidData, "the pixmap's storage now holds " + std::to_string(read) +
                                      " bytes, fewer than the " + std::to_string(bytes) + " of rowBytes * height");
    ScreenPixmap pixmap;
    pixmap.xOffset = d.xOffset;
    pixmap.yOffset = d.yOffset;
    pixmap.width = std::uint32_t(d.pixmap.width);
    pixmap.height = std::uint32_t(d.pixmap.height);
    pixmap.rowBytes = d.pixmap.rowBytes;
    // Checked values of their enumerations.
    pixmap.pixelType = d.pixmap.pixelType;
    pixmap.byteOrder = d.pixmap.byteOrder;
    pixmap.bytes = pixels.data();
    MeshView mesh;
    mesh.pixmaps = &pixmap;
    mesh.pixmapCount = 1;
    drawAt(d.position, mesh, sink);
}

void PixmapMarker::bound(const DecomposeContext&, std::vector<glm::dvec3>& points) const
{
    const TQ3Point3D& p = data().position;
    points.emplace_back(p.x, p.y, p.z);
}

void PixmapMarker::setPosition(const TQ3Point3D& position)
{
    requireFinite(position, "position");
    editableData().position = position;
    markEdited();
}

void PixmapMarker::setXOffset(long xOffset)
{
    editableData().xOffset = xOffset;
    markEdited();
}

void PixmapMarker::setYOffset(long yOffset)
{
    editableData().yOffset = yOffset;
    markEdited();
}

void PixmapMarker::copyPixmap(TQ3StoragePixmap& out) const
{
    TQ3StoragePixmap copy;
    layout::copyData(copy, data().pixmap, layout::RetainTrusted{});
    out = copy;
}

void PixmapMarker::setPixmap(const TQ3StoragePixmap& pixmap)
{
    checkPixmap(pixmap);
    TQ3StoragePixmap fresh;
    layout::copyData(fresh, pixmap, layout::RetainChecked{});
    std::swap(editableData().pixmap, fresh);
    layout::release(fresh);
    markEdited();
}

} // namespace q3
