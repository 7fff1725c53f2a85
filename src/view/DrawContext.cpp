// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/DrawContext.h"

#include "core/EnumValue.h"
#include "core/PixelFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace q3 {

const ClassInfo kDrawContextClass{kQ3SharedTypeDrawContext, &kSharedClass, "draw context"};
const ClassInfo kPixmapDrawContextClass{kQ3DrawContextTypePixmap, &kDrawContextClass,
                                        "pixmap draw context"};

namespace {

// Pane edges are clamped to +-2^29 pixels so that max - min still fits an int.
constexpr double kPaneLimit = double(1 << 29);

TQ3Boolean normalized(const TQ3Boolean& value)
{
    return enumValue(value) != kQ3False ? kQ3True : kQ3False;
}

TQ3DrawContextData normalized(const TQ3DrawContextData& data)
{
    TQ3DrawContextData result = data;
    result.paneState = normalized(data.paneState);
    result.maskState = normalized(data.maskState);
    result.doubleBufferState = normalized(data.doubleBufferState);
    return result;
}

bool isFinite(const TQ3ColorARGB& color)
{
    return std::isfinite(color.a) && std::isfinite(color.r) && std::isfinite(color.g) &&
           std::isfinite(color.b);
}

bool isClearMethod(const TQ3DrawContextClearImageMethod& method)
{
    const long value = enumValue(method);
    return value == kQ3ClearMethodNone || value == kQ3ClearMethodWithColor;
}

int roundEdge(float value)
{
    const double clamped = std::clamp(double(value), -kPaneLimit, kPaneLimit);
    return static_cast<int>(std::floor(clamped + 0.5));
}

} // namespace

void validatePane(const TQ3Area& pane, TQ3Error code)
{
    if (!std::isfinite(pane.min.x) || !std::isfinite(pane.min.y) || !std::isfinite(pane.max.x) ||
        !std::isfinite(pane.max.y))
        fail(code, "a pane coordinate is not a finite number");
    if (!(pane.min.x < pane.max.x) || !(pane.min.y < pane.max.y))
        fail(code, "the pane is empty or inverted (min must be less than max in x and y)");
}

void validateMask(const TQ3Bitmap& mask, TQ3Error code)
{
    if (mask.image == nullptr)
        fail(code, "the mask has no image (mask.image is NULL)");
    if (mask.width == 0 || mask.height == 0)
        fail(code, "the mask is " + std::to_string(mask.width) + " x " + std::to_string(mask.height) +
                       " pixels; both must be at least 1");
    if (mask.rowBytes < mask.width / 8 + (mask.width % 8 != 0 ? 1 : 0))
        fail(code, "mask rowBytes " + std::to_string(mask.rowBytes) + " is too small for a row of " +
                       std::to_string(mask.width) + " bits");
    if (!isEndian(enumValue(mask.bitOrder)))
        fail(code, "mask bitOrder must be kQ3EndianBig or kQ3EndianLittle");
}

void validateDrawContextData(const TQ3DrawContextData& data)
{
    if (!isClearMethod(data.clearImageMethod))
        fail(kQ3ErrorInvalidData, "clearImageMethod " + std::to_string(enumValue(data.clearImageMethod)) +
                                      " is neither kQ3ClearMethodNone nor kQ3ClearMethodWithColor");
    if (!isFinite(data.clearImageColor))
        fail(kQ3ErrorInvalidData, "a clearImageColor component is not a finite number");
    if (normalized(data.paneState) == kQ3True)
        validatePane(data.pane, kQ3ErrorInvalidData);
    if (normalized(data.maskState) == kQ3True)
        validateMask(data.mask, kQ3ErrorInvalidData);
}

void validatePixmap(const TQ3Pixmap& pixmap)
{
    requireNonNull(pixmap.image, "pixmap.image");
    const unsigned long bits = bitsPerPixel(enumValue(pixmap.pixelType));
    if (bits == 0)
        fail(kQ3ErrorInvalidData,
             "pixelType " + std::to_string(enumValue(pixmap.pixelType)) + " is not a TQ3PixelType value");
    if (!isEndian(enumValue(pixmap.byteOrder)) || !isEndian(enumValue(pixmap.bitOrder)))
        fail(kQ3ErrorInvalidData, "byteOrder and bitOrder must be kQ3EndianBig or kQ3EndianLittle");
    if (pixmap.pixelSize != bits)
        fail(kQ3ErrorUnsupportedPixelDepth, "pixelSize " + std::to_string(pixmap.pixelSize) +
                                                " does not fit the pixel type, which has " +
                                                std::to_string(bits) + " bits");
    if (pixmap.width == 0 || pixmap.height == 0)
        fail(kQ3ErrorInvalidData, "the pixmap is " + std::to_string(pixmap.width) + " x " +
                                      std::to_string(pixmap.height) + " pixels; both must be at least 1");
    constexpr unsigned long kMax32 = std::numeric_limits<std::uint32_t>::max();
    if (pixmap.width > kMax32 || pixmap.height > kMax32 || pixmap.rowBytes > kMax32)
        fail(kQ3ErrorInvalidData, "width, height and rowBytes must fit in 32 bits");
    const unsigned long rowMinimum = pixmap.width * (bits / 8);
    if (pixmap.rowBytes < rowMinimum)
        fail(kQ3ErrorInvalidData, "rowBytes " + std::to_string(pixmap.rowBytes) +
                                      " is too small for a row of " + std::to_string(pixmap.width) +
                                      " pixels (" + std::to_string(rowMinimum) + " bytes)");
}

PixmapLayout layoutOf(const TQ3Pixmap& pixmap)
{
    PixmapLayout layout;
    layout.width = static_cast<std::uint32_t>(pixmap.width);
    layout.height = static_cast<std::uint32_t>(pixmap.height);
    layout.rowBytes = static_cast<std::uint32_t>(pixmap.rowBytes);
    layout.pixelType = static_cast<PixelType>(pixmap.pixelType);
    layout.byteOrder = pixmap.byteOrder == kQ3EndianLittle ? ByteOrder::kLittle : ByteOrder::kBig;
    return layout;
}

PixelRect paneRect(const TQ3Area& pane)
{
    PixelRect rect;
    rect.x = roundEdge(pane.min.x);
    rect.y = roundEdge(pane.min.y);
    rect.width = std::max(1, roundEdge(pane.max.x) - rect.x);
    rect.height = std::max(1, roundEdge(pane.max.y) - rect.y);
    return rect;
}

DrawContext::DrawContext(const TQ3DrawContextData& data) : m_data(normalized(data)) {}

void DrawContext::setData(const TQ3DrawContextData& data)
{
    validateDrawContextData(data);
    m_data = normalized(data);
    markEdited();
}

void DrawContext::setClearImageColor(const TQ3ColorARGB& color)
{
    if (!isFinite(color))
        fail(kQ3ErrorInvalidParameter, "a clear colour component is not a finite number");
    m_data.clearImageColor = color;
    markEdited();
}

void DrawContext::setPane(const TQ3Area& pane)
{
    validatePane(pane, kQ3ErrorInvalidParameter);
    m_data.pane = pane;
    markEdited();
}

void DrawContext::setPaneState(const TQ3Boolean& state)
{
    if (normalized(state) == kQ3True)
        validatePane(m_data.pane, kQ3ErrorInvalidParameter);
    m_data.paneState = normalized(state);
    markEdited();
}

void DrawContext::setClearImageMethod(const TQ3DrawContextClearImageMethod& method)
{
    if (!isClearMethod(method))
        fail(kQ3ErrorInvalidParameter,
             "clear method " + std::to_string(enumValue(method)) +
                 " is neither kQ3ClearMethodNone nor kQ3ClearMethodWithColor");
    m_data.clearImageMethod = method;
    markEdited();
}

void DrawContext::setMask(const TQ3Bitmap& mask)
{
    validateMask(mask, kQ3ErrorInvalidParameter);
    m_data.mask = mask;
    markEdited();
}

void DrawContext::setMaskState(const TQ3Boolean& state)
{
    if (normalized(state) == kQ3True)
        validateMask(m_data.mask, kQ3ErrorInvalidParameter);
    m_data.maskState = normalized(state);
    markEdited();
}

void DrawContext::setDoubleBufferState(const TQ3Boolean& state)
{
    m_data.doubleBufferState = normalized(state);
    markEdited();
}

PixelRect DrawContext::drawRect(std::uint32_t width, std::uint32_t height) const
{
    if (m_data.paneState == kQ3True)
        return paneRect(m_data.pane);
    constexpr std::uint32_t kIntMax = std::numeric_limits<int>::max();
    return PixelRect{0, 0, int(std::min(width, kIntMax)), int(std::min(height, kIntMax))};
}

void PixmapDrawContext::validate(const TQ3PixmapDrawContextData& data)
{
    validateDrawContextData(data.drawContextData);
    validatePixmap(data.pixmap);
}

PixmapDrawContext::PixmapDrawContext(const TQ3PixmapDrawContextData& data)
    : DrawContext(data.drawContextData), m_pixmap(data.pixmap)
{
}

Object* PixmapDrawContext::duplicate() const
{
    return makeShared<PixmapDrawContext>(TQ3PixmapDrawContextData{data(), m_pixmap}).detach();
}

void PixmapDrawContext::setPixmap(const TQ3Pixmap& pixmap)
{
    validatePixmap(pixmap);
    m_pixmap = pixmap;
    markEdited();
}

} // namespace q3
