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

struct PickIDRule {
    using Value = unsigned long;
    static constexpr TQ3ObjectType kType = kQ3StyleTypePickID;
    static constexpr Value DrawState::*kField = &DrawState::pickID;
    static const ClassInfo& classInfo() { return kPickIDStyleClass; }
    /// Every ID is valid.
    static Value check(const Value& id) { return id; }
};

struct PickPartsRule {
    using Value = TQ3PickParts;
    static constexpr TQ3ObjectType kType = kQ3StyleTypePickParts;
    static constexpr Value DrawState::*kField = &DrawState::pickParts;
    static const ClassInfo& classInfo() { return kPickPartsStyleClass; }
    /// kQ3PickPartsObject or any combination of the three masks.
    static Value check(const Value& parts);
};

struct CastShadowsRule {
    using Value = TQ3Boolean;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeCastShadows;
    static constexpr Value DrawState::*kField = &DrawState::castShadows;
    static const ClassInfo& classInfo() { return kCastShadowsStyleClass; }
    static Value check(const Value& casts);
};

struct ReceiveShadowsRule {
    using Value = TQ3Boolean;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeReceiveShadows;
    static constexpr Value DrawState::*kField = &DrawState::receiveShadows;
    static const ClassInfo& classInfo() { return kReceiveShadowsStyleClass; }
    static Value check(const Value& receives);
};

struct FillRule {
    using Value = TQ3FillStyle;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeFill;
    static constexpr Value DrawState::*kField = &DrawState::fill;
    static const ClassInfo& classInfo() { return kFillStyleClass; }
    static Value check(const Value& fill);
};

struct BackfacingRule {
    using Value = TQ3BackfacingStyle;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeBackfacing;
    static constexpr Value DrawState::*kField = &DrawState::backfacing;
    static const ClassInfo& classInfo() { return kBackfacingStyleClass; }
    static Value check(const Value& backfacing);
};

struct InterpolationRule {
    using Value = TQ3InterpolationStyle;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeInterpolation;
    static constexpr Value DrawState::*kField = &DrawState::interpolation;
    static const ClassInfo& classInfo() { return kInterpolationStyleClass; }
    static Value check(const Value& interpolation);
};

struct OrientationRule {
    using Value = TQ3OrientationStyle;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeOrientation;
    static constexpr Value DrawState::*kField = &DrawState::orientation;
    static const ClassInfo& classInfo() { return kOrientationStyleClass; }
    static Value check(const Value& orientation);
};

struct AntiAliasRule {
    using Value = TQ3AntiAliasStyleData;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeAntiAlias;
    static constexpr Value DrawState::*kField = &DrawState::antiAlias;
    static const ClassInfo& classInfo() { return kAntiAliasStyleClass; }
    static Value check(const Value& data);
};

struct FogRule {
    using Value = TQ3FogStyleData;
    static constexpr TQ3ObjectType kType = kQ3StyleTypeFog;
    static constexpr Value DrawState::*kField = &DrawState::fog;
    static const ClassInfo& classInfo() { return kFogStyleClass; }
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
