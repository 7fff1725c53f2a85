// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "io/PixmapIO.h"

namespace q3::io {

std::string readPixmapFields(DataReader& in, TQ3StoragePixmap& pixmap)
{
    pixmap.width = in.u32();
    pixmap.height = in.u32();
    pixmap.rowBytes = in.u32();
    pixmap.pixelSize = in.u32();
    pixmap.pixelType = static_cast<TQ3PixelType>(in.choice(kPixelTypes));
    pixmap.bitOrder = static_cast<TQ3Endian>(in.choice(kEndians));
    pixmap.byteOrder = static_cast<TQ3Endian>(in.choice(kEndians));
    const std::uint64_t size = std::uint64_t{pixmap.height} * pixmap.rowBytes;
    in.requireRoom(size, 1, 0, "image bytes");
    return in.rawData(static_cast<std::size_t>(size));
}

void writePixmapFields(Encoder& out, const TQ3StoragePixmap& pixmap, const std::vector<unsigned char>& image)
{
    out.u32(static_cast<std::uint32_t>(pixmap.width));
    out.u32(static_cast<std::uint32_t>(pixmap.height));
    out.u32(static_cast<std::uint32_t>(pixmap.rowBytes));
    out.u32(static_cast<std::uint32_t>(pixmap.pixelSize));
    out.choice(kPixelTypes, static_cast<std::uint32_t>(pixmap.pixelType));
    out.choice(kEndians, static_cast<std::uint32_t>(pixmap.bitOrder));
    out.choice(kEndians, static_cast<std::uint32_t>(pixmap.byteOrder));
    out.rawData(image.data(), image.size());
}

Ref<MemoryStorage> storageOf(const std::string& bytes)
{
    return makeShared<MemoryStorage>(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

} // namespace q3::io
