// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "style/ValueStyles.h"

#include "core/ParameterChecks.h"

#include <string>

namespace q3 {

const ClassInfo kPickIDStyleClass{kQ3StyleTypePickID, &kStyleClass, "pick ID style"};
const ClassInfo kPickPartsStyleClass{kQ3StyleTypePickParts, &kStyleClass, "pick parts style"};
const ClassInfo kCastShadowsStyleClass{kQ3StyleTypeCastShadows, &kStyleClass, "cast shadows style"};
const ClassInfo kReceiveShadowsStyleClass{kQ3StyleTypeReceiveShadows, &kStyleClass, "receive shadows style"};
const ClassInfo kFillStyleClass{kQ3StyleTypeFill, &kStyleClass, "fill style"};
const ClassInfo kBackfacingStyleClass{kQ3StyleTypeBackfacing, &kStyleClass, "backfacing style"};
const ClassInfo kInterpolationStyleClass{kQ3StyleTypeInterpolation, &kStyleClass, "interpolation style"};
const ClassInfo kOrientationStyleClass{kQ3StyleTypeOrientation, &kStyleClass, "orientation style"};
const ClassInfo kAntiAliasStyleClass{kQ3StyleTypeAntiAlias, &kStyleClass, "anti-alias style"};
const ClassInfo kFogStyleClass{kQ3StyleTypeFog, &kStyleClass, "fog style"};

namespace {

constexpr unsigned long kAllPickParts = kQ3PickPartsMaskFace | kQ3PickPartsMaskEdge | kQ3PickPartsMaskVertex;
constexpr unsigned long kAllAntiAliasModes = kQ3AntiAliasModeMaskEdges | kQ3AntiAliasModeMaskFilled;

void checkMask(unsigned long value, unsigned long allowed, const char* name, const char* masks)
{
    if ((value & ~allowed) != 0)
        fail(kQ3ErrorInvalidParameter, std::string(name) + " " + std::to_string(value) +
                                           " has bits outside " + masks);
}

} // namespace

PickPartsRule::Value PickPartsRule::check(const Value& parts)
{
    checkMask(parts, kAllPickParts, "parts", "kQ3PickPartsMaskFace | Edge | Vertex");
    return parts;
}

CastShadowsRule::Value CastShadowsRule::check(const Value& casts)
{
    return booleanOf(casts);
}

ReceiveShadowsRule::Value ReceiveShadowsRule::check(const Value& receives)
{
    return booleanOf(receives);
}

FillRule::Value FillRule::check(const Value& fill)
{
    return checkEnum(fill, kQ3FillStyleFilled, kQ3FillStylePoints, "fillStyle",
                     "kQ3FillStyleFilled, Edges, Points");
}

BackfacingRule::Value BackfacingRule::check(const Value& backfacing)
{
    return checkEnum(backfacing, kQ3BackfacingStyleBoth, kQ3BackfacingStyleFlip, "backfacingStyle",
                     "kQ3BackfacingStyleBoth, Remove, Flip");
}

InterpolationRule::Value InterpolationRule::check(const Value& interpolation)
{
    return checkEnum(interpolation, kQ3InterpolationStyleNone, kQ3InterpolationStylePixel,
                     "interpolationStyle", "kQ3InterpolationStyleNone, Vertex, Pixel");
}

OrientationRule::Value OrientationRule::check(const Value& orientation)
{
    return checkEnum(orientation, kQ3OrientationStyleCounterClockwise, kQ3OrientationStyleClockwise,
                     "frontFacingDirection", "kQ3OrientationStyleCounterClockwise, Clockwise");
}

AntiAliasRule::Value AntiAliasRule::check(const Value& data)
{
    Value result;
    result.state = checkSwitch(data.state, "data->state");
    checkMask(data.mode, kAllAntiAliasModes, "data->mode", "kQ3AntiAliasModeMaskEdges | Filled");
    result.mode = data.mode;
    checkFinite(data.quality, "data->quality");
    if (!(data.quality >= 0.0f && data.quality <= 1.0f))
        fail(kQ3ErrorInvalidParameter,
             "data->quality " + std::to_string(data.quality) + " is outside 0 to 1");
    result.quality = data.quality;
    return result;
}

FogRule::Value FogRule::check(const Value& data)
{
    Value result;
    result.state = checkSwitch(data.state, "data->state");
    result.mode = checkEnum(data.mode, kQ3FogModeLinear, kQ3FogModeAlpha, "data->mode",
                            "kQ3FogModeLinear, Exponential, ExponentialSquared, Alpha");
    checkFinite(data.fogStart, "data->fogStart");
    checkFinite(data.fogEnd, "data->fogEnd");
    checkFinite(data.density, "data->density");
    checkFinite(data.color, "data->color");
    if (data.density < 0.0f)
        fail(kQ3ErrorInvalidParameter, "data->density " + std::to_string(data.density) + " is negative");
    // Linear fog divides by fogEnd - fogStart; fog that is off, or of another
    // mode, keeps whatever the caller left in the fields it does not use.
    if (result.state == kQ3On && result.mode == kQ3FogModeLinear && !(data.fogStart < data.fogEnd))
        fail(kQ3ErrorInvalidParameter, "linear fog needs data->fogStart " + std::to_string(data.fogStart) +
                                           " below data->fogEnd " + std::to_string(data.fogEnd));
    result.fogStart = data.fogStart;
    result.fogEnd = data.fogEnd;
    result.density = data.density;
    result.color = data.color;
    return result;
}

} // namespace q3
