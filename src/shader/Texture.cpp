// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "shader/Texture.h"

#include "core/EnumValue.h"
#include "core/PixelFormat.h"
#include "core/Limits.h"
#include "core/Ref.h"
// Textures keep their images in storage objects (QD3DStorage.h), whose
// interface depends only on core, as the pixmap marker's does.
#include "base/Storage.h"

#include <algorithm>
#include <string>
#include <utility>

namespace q3 {

const ClassInfo kTextureClass{kQ3SharedTypeTexture, &kSharedClass, "texture"};
const ClassInfo kPixmapTextureClass{kQ3TextureTypePixmap, &kTextureClass, "pixmap texture"};
const ClassInfo kMipmapTextureClass{kQ3TextureTypeMipmap, &kTextureClass, "mipmap texture"};

namespace {

std::string text(unsigned long value)
{
    return std::to_string(value);
}

/// The pixel type and the byte and bit orders; returns the bits per pixel.
unsigned long checkPixelFormat(const TQ3PixelType& pixelType, const TQ3Endian& byteOrder, const TQ3Endian& bitOrder,
                               const std::string& prefix)
{
    const long type = enumValue(pixelType);
    const unsigned long bits = bitsPerPixel(type);
    if (bits == 0)
        fail(kQ3ErrorInvalidData, prefix + "pixelType " + std::to_string(type) + " is not a TQ3PixelType");
    for (const auto& [value, name] : {std::pair{enumValue(byteOrder), "byteOrder"},
                                      std::pair{enumValue(bitOrder), "bitOrder"}})
        if (!isEndian(value))
            fail(kQ3ErrorInvalidData, prefix + name + " " + std::to_string(value) + " is not a TQ3Endian");
    return bits;
}

/// One image's size, rows and place in a storage of `held` bytes.
void checkImage(unsigned long width, unsigned long height, unsigned long rowBytes, unsigned long offset,
                unsigned long bits, std::size_t held, const std::string& name)
{
    if (width == 0 || height == 0 || width > limits::kMaxTextureSize || height > limits::kMaxTextureSize)
        fail(kQ3ErrorInvalidData, name + " is " + text(width) + " x " + text(height) + " pixels; a texture image is 1 to " +
                                      text(limits::kMaxTextureSize) + " pixels wide and high");
    // Compared by division, so width * bytes per pixel cannot overflow.
    if (rowBytes / (bits / 8) < width)
        fail(kQ3ErrorInvalidData, name + ".rowBytes " + text(rowBytes) + " cannot hold " + text(width) +
                                      " pixels of " + text(bits) + " bits");
    // Compared by division, so offset + rowBytes * height cannot overflow.
    if (offset > held || rowBytes > (held - offset) / height)
        fail(kQ3ErrorInvalidData, name + " needs " + (offset != 0 ? "offset " + text(offset) + " + " : std::string()) +
                                      "rowBytes * height = " + text(rowBytes) + " * " + text(height) +
                                      " bytes; the storage holds " + text(held));
}

const Storage& storageOf(TQ3StorageObject image)
{
    return *static_cast<const Storage*>(static_cast<Object*>(image));
}

TexturePixels readPixels(TQ3StorageObject image, std::size_t offset, unsigned long width, unsigned long height,
                         unsigned long rowBytes, TQ3PixelType pixelType, TQ3Endian byteOrder, PixelAccess access)
{
    TexturePixels pixels;
    const std::size_t bytes = std::size_t(rowBytes) * height;
    const Storage& storage = storageOf(image);
    if (access == PixelAccess::kInPlace)
        pixels.inPlace = storage.inPlace(offset, bytes);
    std::size_t read = bytes;
    if (pixels.inPlace == nullptr) {
        pixels.bytes.resize(bytes);
        read = storage.size() >= offset ? storage.read(offset, bytes, pixels.bytes.data()) : 0;
    }
    if (read < bytes)
        fail(kQ3ErrorInvalidData, "the texture's storage now holds " + text(storage.size()) + " bytes, fewer than the " +
                                      text(offset + bytes) + " its image needs");
    pixels.width = std::uint32_t(width);
    pixels.height = std::uint32_t(height);
    pixels.rowBytes = rowBytes;
    pixels.pixelType = pixelType;
    pixels.byteOrder = byteOrder;
    pixels.sourceVersion = storage.contentVersion();
    pixels.sourceOffset = offset;
    return pixels;
}

/// A new counted reference to the storage behind `image`, handed to C.
TQ3StorageObject retained(TQ3StorageObject image)
{
    Storage& storage = const_cast<Storage&>(storageOf(image));
    return Ref<Storage>::retain(&storage).detach();
}

void release(TQ3StorageObject image)
{
    const_cast<Storage&>(storageOf(image)).releaseReference();
}

} // namespace

void PixmapTexture::check(const TQ3StoragePixmap& pixmap)
{
    const Storage& storage = lookup<Storage>(pixmap.image, "pixmap->image");
    const unsigned long bits = checkPixelFormat(pixmap.pixelType, pixmap.byteOrder, pixmap.bitOrder, "pixmap->");
    if (pixmap.pixelSize != bits)
        fail(kQ3ErrorUnsupportedPixelDepth, "pixmap->pixelSize " + text(pixmap.pixelSize) + " is not the " + text(bits) +
                                                " bits of its pixel type");
    checkImage(pixmap.width, pixmap.height, pixmap.rowBytes, 0, bits, storage.size(), "pixmap");
}

TexturePixels PixmapTexture::readImage(PixelAccess access) const
{
    const TQ3StoragePixmap& pixmap = held();
    return readPixels(pixmap.image, 0, pixmap.width, pixmap.height, pixmap.rowBytes, pixmap.pixelType,
                      pixmap.byteOrder, access);
}

unsigned MipmapTexture::imageCount(const TQ3Mipmap& mipmap)
{
    if (mipmap.useMipmapping != kQ3True)
        return 1;
    unsigned long side = std::max(mipmap.mipmaps[0].width, mipmap.mipmaps[0].height);
    unsigned count = 1;
    while (side > 1) {
        side >>= 1;
        ++count;
    }
    return count;
}

void MipmapTexture::check(const TQ3Mipmap& mipmap)
{
    const Storage& storage = lookup<Storage>(mipmap.image, "mipmap->image");
    const long use = enumValue(mipmap.useMipmapping);
    if (use != kQ3False && use != kQ3True)
        fail(kQ3ErrorInvalidData, "mipmap->useMipmapping " + std::to_string(use) + " is not kQ3False or kQ3True");
    const unsigned long bits = checkPixelFormat(mipmap.pixelType, mipmap.byteOrder, mipmap.bitOrder, "mipmap->");
    if (mipmap.reserved != 0)
        fail(kQ3ErrorInvalidData, "mipmap->reserved is " + text(mipmap.reserved) + ", not 0");
    const std::size_t held = storage.size();
    const TQ3MipmapImage& first = mipmap.mipmaps[0];
    checkImage(first.width, first.height, first.rowBytes, first.offset, bits, held, "mipmap->mipmaps[0]");
    if (use != kQ3True)
        return;
    const auto powerOfTwo = [](unsigned long n) { return (n & (n - 1)) == 0; };
    if (!powerOfTwo(first.width) || !powerOfTwo(first.height))
        fail(kQ3ErrorInvalidData, "mipmap->mipmaps[0] is " + text(first.width) + " x " + text(first.height) +
                                      "; with useMipmapping its sides must be powers of 2");
    const unsigned count = imageCount(mipmap);
    for (unsigned i = 1; i < count; ++i) {
        const TQ3MipmapImage& image = mipmap.mipmaps[i];
        const std::string name = "mipmap->mipmaps[" + std::to_string(i) + "]";
        const unsigned long width = std::max(1ul, first.width >> i), height = std::max(1ul, first.height >> i);
        if (image.width != width || image.height != height)
            fail(kQ3ErrorInvalidData, name + " is " + text(image.width) + " x " + text(image.height) + ", not the " +
                                          text(width) + " x " + text(height) + " that halves the image before it");
        checkImage(image.width, image.height, image.rowBytes, image.offset, bits, held, name);
    }
}

TexturePixels MipmapTexture::readImage(PixelAccess access) const
{
    const TQ3Mipmap& mipmap = held();
    const TQ3MipmapImage& first = mipmap.mipmaps[0];
    return readPixels(mipmap.image, first.offset, first.width, first.height, first.rowBytes, mipmap.pixelType,
                      mipmap.byteOrder, access);
}

std::vector<TexturePixels> MipmapTexture::readMipmaps(PixelAccess access) const
{
    std::vector<TexturePixels> images;
    const TQ3Mipmap& mipmap = held();
    const unsigned count = imageCount(mipmap);
    for (unsigned i = 1; i < count; ++i) {
        const TQ3MipmapImage& image = mipmap.mipmaps[i];
        images.push_back(readPixels(mipmap.image, image.offset, image.width, image.height, image.rowBytes,
                                    mipmap.pixelType, mipmap.byteOrder, access));
    }
    return images;
}

template <class Derived, class Description>
StorageTexture<Derived, Description>::StorageTexture(const Description& description)
{
    Derived::check(description);
    m_description = description;
    m_description.image = retained(description.image);
}

template <class Derived, class Description>
StorageTexture<Derived, Description>::~StorageTexture()
{
    release(m_description.image);
}

template <class Derived, class Description>
Object* StorageTexture<Derived, Description>::duplicate() const
{
    return makeShared<Derived>(m_description).detach();
}

template <class Derived, class Description>
Description StorageTexture<Derived, Description>::described() const
{
    Description copy = m_description;
    copy.image = retained(m_description.image);
    return copy;
}

template <class Derived, class Description>
void StorageTexture<Derived, Description>::describe(const Description& description)
{
    Derived::check(description);
    const TQ3StorageObject old = m_description.image;
    m_description = description;
    m_description.image = retained(description.image);
    release(old);
    markEdited();
}

template class StorageTexture<PixmapTexture, TQ3StoragePixmap>;
template class StorageTexture<MipmapTexture, TQ3Mipmap>;

} // namespace q3
