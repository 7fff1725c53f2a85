// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DDrawContext.h"
#include "core/Object.h"
#include "base/PixelConvert.h"
#include "base/RenderResult.h"

namespace q3 {

extern const ClassInfo kDrawContextClass;
extern const ClassInfo kPixmapDrawContextClass;

/// Checks the TQ3DrawContextData rules of QD3DDrawContext.h; throws
/// kQ3ErrorInvalidData naming the broken rule.
void validateDrawContextData(const TQ3DrawContextData& data);

/// Checks a pane (finite, min < max in x and y); throws `code`.
void validatePane(const TQ3Area& pane, TQ3Error code);

/// Checks the mask rules of QD3DDrawContext.h; throws `code`.
void validateMask(const TQ3Bitmap& mask, TQ3Error code);

/// Checks the TQ3Pixmap rules of QD3DDrawContext.h in their order
/// (kQ3ErrorNULLParameter, kQ3ErrorInvalidData,
/// kQ3ErrorUnsupportedPixelDepth, kQ3ErrorInvalidData). Beyond the header's
/// rules, width, height and rowBytes must fit in 32 bits (kQ3ErrorInvalidData).
void validatePixmap(const TQ3Pixmap& pixmap);

/// The PixelConvert description of a valid pixmap.
PixmapLayout layoutOf(const TQ3Pixmap& pixmap);

/// The pixels a pane covers: each edge rounded to the nearest pixel boundary,
/// at least one pixel wide and high. Coordinates beyond +-2^30 are clamped
/// first (the renderer rejects such panes anyway).
PixelRect paneRect(const TQ3Area& pane);

/// State common to every draw context. Invariant: the stored data obey
/// validateDrawContextData, with every TQ3Boolean field exactly kQ3True or
/// kQ3False.
class DrawContext : public SharedObject {
public:
    static constexpr TQ3ObjectType kClassType = kQ3SharedTypeDrawContext;

    const TQ3DrawContextData& data() const { return m_data; }
    /// Each setter validates first and changes nothing on failure: setData
    /// throws kQ3ErrorInvalidData, the others kQ3ErrorInvalidParameter.
    void setData(const TQ3DrawContextData& data);
    void setClearImageColor(const TQ3ColorARGB& color);
    void setPane(const TQ3Area& pane);
    /// Enum arguments come by reference: a C caller may pass any int, which
    /// is checked through enumValue (core/EnumValue.h) before use.
    void setPaneState(const TQ3Boolean& state);
    void setClearImageMethod(const TQ3DrawContextClearImageMethod& method);
    void setMask(const TQ3Bitmap& mask);
    void setMaskState(const TQ3Boolean& state);
    void setDoubleBufferState(const TQ3Boolean& state);

    /// The pixels drawn into in an image of width x height: the pane when
    /// the pane state is on, the whole image otherwise.
    PixelRect drawRect(std::uint32_t width, std::uint32_t height) const;

protected:
    /// Takes data that passed validateDrawContextData.
    explicit DrawContext(const TQ3DrawContextData& data);

private:
    TQ3DrawContextData m_data;
};

/// A draw context rendering into caller-owned memory. Invariant: the pixmap
/// obeys validatePixmap; Q3 never frees or copies its image.
class PixmapDrawContext final : public DrawContext {
public:
    static constexpr TQ3ObjectType kClassType = kQ3DrawContextTypePixmap;

    /// Validates both parts in the order of Q3PixmapDrawContext_New.
    static void validate(const TQ3PixmapDrawContextData& data);
    /// Takes validated data.
    explicit PixmapDrawContext(const TQ3PixmapDrawContextData& data);

    const ClassInfo& classInfo() const override { return kPixmapDrawContextClass; }
    Object* duplicate() const override;

    const TQ3Pixmap& pixmap() const { return m_pixmap; }
    void setPixmap(const TQ3Pixmap& pixmap);

private:
    TQ3Pixmap m_pixmap;
};

} // namespace q3
