// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

#include "Q3Exchange.h"

#include "api/Entry.h"
#include "core/EnumValue.h"
#include "exchange/Exchange.h"
#include "group/Group.h"
#include "view/Camera.h"
#include "view/DrawContext.h"
#include "view/View.h"

#include <cmath>

using namespace q3;
using namespace q3::api;

namespace {

// A C caller may put any int in an enum-typed field or argument: each is
// read as bytes (core/EnumValue.h) and checked before it is used as the enum.
TQ3ExchangeFormat checkedFormat(const TQ3ExchangeFormat& format, const char* name)
{
    const long value = enumValue(format);
    if (value < kQ3ExchangeFormatAny || value > kQ3ExchangeFormatSTL)
        fail(kQ3ErrorInvalidParameter, std::string(name) + " " + std::to_string(value) + " is not a TQ3ExchangeFormat");
    return static_cast<TQ3ExchangeFormat>(value);
}

exchange::SubdivisionChoice subdivisionOf(const TQ3ExchangeOptions& options)
{
    exchange::SubdivisionChoice choice;
    if (enumValue(options.subdivisionFromSize) != kQ3False)
        return choice;
    if (options.view != nullptr) {
        // The window the view's rendering loop would have.
        const View& view = lookup<View>(options.view, "options->view");
        const auto* context = dynamic_cast<const PixmapDrawContext*>(view.drawContext().get());
        if (view.camera() && context != nullptr) {
            const PixmapLayout layout = layoutOf(context->pixmap());
            choice.window = Window{view.camera()->worldToFrustum(), context->drawRect(layout.width, layout.height)};
        }
    }
    const long method = enumValue(options.subdivisionMethod);
    if (method != kQ3SubdivisionMethodWorldSpace && method != kQ3SubdivisionMethodConstant &&
        !(method == kQ3SubdivisionMethodScreenSpace && choice.window))
        fail(kQ3ErrorInvalidParameter, "options->subdivisionMethod is none of world space, constant, and screen "
                                       "space with a view that has a camera and a pixmap draw context");
    if (!std::isfinite(options.subdivisionValue) || !(options.subdivisionValue > 0.0f))
        fail(kQ3ErrorInvalidParameter, "options->subdivisionValue is not finite and greater than 0");
    choice.fromBounds = false;
    choice.style = TQ3SubdivisionStyleData{static_cast<TQ3SubdivisionMethod>(method), options.subdivisionValue,
                                           options.subdivisionValue};
    return choice;
}

} // namespace

extern "C" {

TQ3Status Q3Exchange_InitOptions(TQ3ExchangeOptions* options)
{
    return guardStatus(__func__, [&] {
        requireNonNull(options, "options");
        *options = TQ3ExchangeOptions{kQ3ExchangeFormatAny, kQ3True, kQ3SubdivisionMethodWorldSpace, 1.0f, nullptr};
    });
}

TQ3Status Q3Exchange_Write(TQ3Object object, const char* path, const TQ3ExchangeOptions* options)
{
    return guardStatus(__func__, [&] {
        const Object& source = lookupObject(object, "object");
        requireNonNull(path, "path");
        const TQ3ExchangeOptions chosen =
            options != nullptr ? *options : TQ3ExchangeOptions{kQ3ExchangeFormatAny, kQ3True, kQ3SubdivisionMethodWorldSpace, 1.0f, nullptr};
        const TQ3ExchangeFormat format = checkedFormat(chosen.format, "options->format");
        exchange::writeFile(source, path, format, subdivisionOf(chosen));
    });
}

TQ3GroupObject Q3Exchange_Read(const char* path, TQ3ExchangeFormat format)
{
    return guard(__func__, TQ3GroupObject{nullptr}, [&]() -> TQ3GroupObject {
        requireNonNull(path, "path");
        return exchange::readFile(path, checkedFormat(format, "format")).detach();
    });
}

} // extern "C"
