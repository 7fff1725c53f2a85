// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// The QuickDraw 3D styles whose data is one value (QD3DStyle.h), each a
// ValueStyle described by its rule: the type code, the DrawState field it
// sets, and the check its value must pass. The checks, in ValueStyles.cpp,
// are the rules QD3DStyle.h documents.

#include "QD3DStyle.h"
#include "style/ValueStyle.h"

namespace q3 {

extern const ClassInfo kPickIDStyleClass;
extern const ClassInfo kPickPartsStyleClass;
extern const ClassInfo kCastShadowsStyleClass;
extern const ClassInfo kReceiveShadowsStyleClass;
extern const ClassInfo kFillStyleClass;
extern const ClassInfo kBackfacingStyleClass;
extern const ClassInfo kInterpolationStyleClass;
extern const ClassInfo kOrientationStyleClass;
extern const ClassInfo kAntiAliasStyleClass;
extern const ClassInfo kFogStyleClass;

/// What every rule below shares: the value's type, the style's type code,
/// the DrawState field it sets and its class.
template <class V, TQ3ObjectType Type, V DrawState::*Field, const ClassInfo& Info>
struct ValueStyleRule {
    using Value = V;
    static constexpr TQ3ObjectType kType = Type;
    static constexpr Value DrawState::*kField = Field;
    static const ClassInfo& classInfo() { return Info; }
};

struct PickIDRule : ValueStyleRule<unsigned long, kQ3StyleTypePickID, &DrawState::pickID, kPickIDStyleClass> {
    /// Every ID is valid.
    static Value check(const Value& id) { return id; }
};

struct PickPartsRule
    : ValueStyleRule<TQ3PickParts, kQ3StyleTypePickParts, &DrawState::pickParts, kPickPartsStyleClass> {
    /// kQ3PickPartsObject or any combination of the three masks.
    static Value check(const Value& parts);
};

struct CastShadowsRule
    : ValueStyleRule<TQ3Boolean, kQ3StyleTypeCastShadows, &DrawState::castShadows, kCastShadowsStyleClass> {
    static Value check(const Value& casts);
};

struct ReceiveShadowsRule
    : ValueStyleRule<TQ3Boolean, kQ3StyleTypeReceiveShadows, &DrawState::receiveShadows, kReceiveShadowsStyleClass> {
    static Value check(const Value& receives);
};

struct FillRule : ValueStyleRule<TQ3FillStyle, kQ3StyleTypeFill, &DrawState::fill, kFillStyleClass> {
    static Value check(const Value& fill);
};

struct BackfacingRule
    : ValueStyleRule<TQ3BackfacingStyle, kQ3StyleTypeBackfacing, &DrawState::backfacing, kBackfacingStyleClass> {
    static Value check(const Value& backfacing);
};

struct InterpolationRule
    : ValueStyleRule<TQ3InterpolationStyle, kQ3StyleTypeInterpolation, &DrawState::interpolation,
                     kInterpolationStyleClass> {
    static Value check(const Value& interpolation);
};

struct OrientationRule
    : ValueStyleRule<TQ3OrientationStyle, kQ3StyleTypeOrientation, &DrawState::orientation, kOrientationStyleClass> {
    static Value check(const Value& orientation);
};

struct AntiAliasRule
    : ValueStyleRule<TQ3AntiAliasStyleData, kQ3StyleTypeAntiAlias, &DrawState::antiAlias, kAntiAliasStyleClass> {
    static Value check(const Value& data);
};

struct FogRule : ValueStyleRule<TQ3FogStyleData, kQ3StyleTypeFog, &DrawState::fog, kFogStyleClass> {
    static Value check(const Value& data);
};

using PickIDStyle = ValueStyle<PickIDRule>;
using PickPartsStyle = ValueStyle<PickPartsRule>;
using CastShadowsStyle = ValueStyle<CastShadowsRule>;
using ReceiveShadowsStyle = ValueStyle<ReceiveShadowsRule>;
using FillStyle = ValueStyle<FillRule>;
using BackfacingStyle = ValueStyle<BackfacingRule>;
using InterpolationStyle = ValueStyle<InterpolationRule>;
using OrientationStyle = ValueStyle<OrientationRule>;
using AntiAliasStyle = ValueStyle<AntiAliasRule>;
using FogStyle = ValueStyle<FogRule>;

} // namespace q3
