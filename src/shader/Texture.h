// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// QD3DShader.h's textures: a pixmap texture (one image, TQ3StoragePixmap)
// and a mipmap texture (one image or a chain, TQ3Mipmap), each kept in a
// storage object that the texture references and reads when it is drawn.

#include "QD3DShader.h"
#include "core/Object.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace q3 {

class Storage;

extern const ClassInfo kTextureClass;
extern const ClassInfo kPixmapTextureClass;
extern const ClassInfo kMipmapTextureClass;

/// One image read out of a texture's storage: `height` rows of `rowBytes`
/// bytes, top row first, each pixel a word of pixelType's layout stored in
/// byteOrder. The fields obey the texture's data rules.
struct TexturePixels {
    /// A copy of the bytes, unless `inPlace` is set.
    std::vector<unsigned char> bytes;
    /// Read with PixelAccess::kInPlace from a storage holding them in
    /// memory: the storage's own bytes, valid until the storage changes.
    const unsigned char* inPlace = nullptr;
    const unsigned char* data() const { return inPlace != nullptr ? inPlace : bytes.data(); }
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::size_t rowBytes = 0;
    TQ3PixelType pixelType = kQ3PixelTypeARGB32;
    TQ3Endian byteOrder = kQ3EndianBig;
    /// Where the bytes came from: the storage's contentVersion (0: unknown)
    /// and their offset in it.
    unsigned long sourceVersion = 0;
    std::size_t sourceOffset = 0;
};

/// How a texture's images are read: copied, or where the storage holds them
/// in memory, pointed to (for a caller that uses them at once).
enum class PixelAccess { kCopy, kInPlace };

/// Every texture. Invariant: its data obeys QD3DShader.h's data rules (which
/// the constructors and setters check before changing anything) and it holds
/// one reference to its storage.
class Texture : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeTexture;

    /// The first image's size.
    virtual unsigned long width() const = 0;
    virtual unsigned long height() const = 0;
    /// The first image, read from the storage now; throws
    /// kQ3ErrorInvalidData when the storage no longer holds it.
    virtual TexturePixels readImage(PixelAccess access = PixelAccess::kCopy) const = 0;
    /// The images after the first (a mipmap chain's smaller ones, each half
    /// the one before, down to 1 x 1), read now; none for a texture of one
    /// image. Throws as readImage.
    virtual std::vector<TexturePixels> readMipmaps(PixelAccess = PixelAccess::kCopy) const { return {}; }

protected:
    Texture() = default;
};

/// A texture kept as its QD3DShader.h description (a TQ3StoragePixmap, a
/// TQ3Mipmap), whose `image` is the storage holding its pixels. Invariant:
/// the description passed Derived::check, and the texture holds one
/// reference to its storage.
template <class Derived, class Description>
class StorageTexture : public Texture {
public:
    /// Checks, then references description.image.
    explicit StorageTexture(const Description& description);
    ~StorageTexture() override;

    /// A copy sharing the storage, as a duplicated pixmap marker does.
    Object* duplicate() const override;

protected:
    const Description& held() const { return m_description; }
    /// The description with a new reference to the storage.
    Description described() const;
    /// Checks, references the new storage, releases the old one.
    void describe(const Description& description);

private:
    Description m_description;
};

/// A texture of one image (Q3PixmapTexture_).
class PixmapTexture final : public StorageTexture<PixmapTexture, TQ3StoragePixmap> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TextureTypePixmap;

    /// QD3DShader.h's data rules for a pixmap, in their order.
    static void check(const TQ3StoragePixmap& pixmap);
    using StorageTexture::StorageTexture;

    const ClassInfo& classInfo() const override { return kPixmapTextureClass; }
    unsigned long width() const override { return held().width; }
    unsigned long height() const override { return held().height; }
    TexturePixels readImage(PixelAccess access) const override;

    TQ3StoragePixmap pixmap() const { return described(); }
    void setPixmap(const TQ3StoragePixmap& pixmap) { describe(pixmap); }
};

/// A texture of one image or a chain of halving images (Q3MipmapTexture_).
class MipmapTexture final : public StorageTexture<MipmapTexture, TQ3Mipmap> {
public:
    static constexpr TQ3ObjectType kClassType = kQ3TextureTypeMipmap;

    /// QD3DShader.h's data rules for a mipmap, in their order.
    static void check(const TQ3Mipmap& mipmap);
    using StorageTexture::StorageTexture;

    const ClassInfo& classInfo() const override { return kMipmapTextureClass; }
    unsigned long width() const override { return held().mipmaps[0].width; }
    unsigned long height() const override { return held().mipmaps[0].height; }
    TexturePixels readImage(PixelAccess access) const override;
    /// With useMipmapping, mipmaps[1] onwards.
    std::vector<TexturePixels> readMipmaps(PixelAccess access) const override;

    /// How many images the data rules read: 1, or with useMipmapping one
    /// more than log2 of the first image's larger side.
    static unsigned imageCount(const TQ3Mipmap& mipmap);
    TQ3Mipmap mipmap() const { return described(); }
    void setMipmap(const TQ3Mipmap& mipmap) { describe(mipmap); }
};

} // namespace q3
