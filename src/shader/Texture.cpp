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
                         unsigned long rowBytes, TQ3PixelType pixelType, TQ3Endian byteOrder)
{
    TexturePixels pixels;
    const std::size_t bytes = std::size_t(rowBytes) * height;
    pixels.bytes.resize(bytes);
    const Storage& storage = storageOf(image);
    const std::size_t read = storage.size() >= offset ? storage.read(offset, bytes, pixels.bytes.data()) : 0;
    if (read < bytes)
        fail(kQ3ErrorInvalidData, "the texture's storage now holds " + text(storage.size()) + " bytes, fewer than the " +
                                      text(offset + bytes) + " its image needs");
    pixels.width = std::uint32_t(width);
    pixels.height = std::uint32_t(height);
    pixels.rowBytes = rowBytes;
    pixels.pixelType = pixelType;
    pixels.byteOrder = byteOrder;
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

PixmapTexture::PixmapTexture(const TQ3StoragePixmap& pixmap)
{
    check(pixmap);
    m_pixmap = pixmap;
    m_pixmap.image = retained(pixmap.image);
}

PixmapTexture::~PixmapTexture()
{
    release(m_pixmap.image);
}

Object* PixmapTexture::duplicate() const
{
    // The copy shares the storage, as a duplicated pixmap marker does.
    return makeShared<PixmapTexture>(m_pixmap).detach();
}

TexturePixels PixmapTexture::readImage() const
{
    return readPixels(m_pixmap.image, 0, m_pixmap.width, m_pixmap.height, m_pixmap.rowBytes, m_pixmap.pixelType,
                      m_pixmap.byteOrder);
}

TQ3StoragePixmap PixmapTexture::pixmap() const
{
    TQ3StoragePixmap copy = m_pixmap;
    copy.image = retained(m_pixmap.image);
    return copy;
}

void PixmapTexture::setPixmap(const TQ3StoragePixmap& pixmap)
{
    check(pixmap);
    const TQ3StorageObject old = m_pixmap.image;
    m_pixmap = pixmap;
    m_pixmap.image = retained(pixmap.image);
    release(old);
    markEdited();
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

MipmapTexture::MipmapTexture(const TQ3Mipmap& mipmap)
{
    check(mipmap);
    m_mipmap = mipmap;
    m_mipmap.image = retained(mipmap.image);
}

MipmapTexture::~MipmapTexture()
{
    release(m_mipmap.image);
}

Object* MipmapTexture::duplicate() const
{
    return makeShared<MipmapTexture>(m_mipmap).detach();
}

TexturePixels MipmapTexture::readImage() const
{
    const TQ3MipmapImage& first = m_mipmap.mipmaps[0];
    return readPixels(m_mipmap.image, first.offset, first.width, first.height, first.rowBytes, m_mipmap.pixelType,
                      m_mipmap.byteOrder);
}

std::vector<TexturePixels> MipmapTexture::readMipmaps() const
{
    std::vector<TexturePixels> images;
    const unsigned count = imageCount(m_mipmap);
    for (unsigned i = 1; i < count; ++i) {
        const TQ3MipmapImage& image = m_mipmap.mipmaps[i];
        images.push_back(readPixels(m_mipmap.image, image.offset, image.width, image.height, image.rowBytes,
                                    m_mipmap.pixelType, m_mipmap.byteOrder));
    }
    return images;
}

TQ3Mipmap MipmapTexture::mipmap() const
{
    TQ3Mipmap copy = m_mipmap;
    copy.image = retained(m_mipmap.image);
    return copy;
}

void MipmapTexture::setMipmap(const TQ3Mipmap& mipmap)
{
    check(mipmap);
    const TQ3StorageObject old = m_mipmap.image;
    m_mipmap = mipmap;
    m_mipmap.image = retained(mipmap.image);
    release(old);
    markEdited();
}

} // namespace q3
