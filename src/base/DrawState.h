// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "core/AttributeSet.h"
#include "core/Limits.h"
#include "core/Ref.h"

namespace q3 {

/// A subdivision method as messages name it ("screen-space"); "unknown" for
/// a value that is none of the three.
inline const char* subdivisionMethodName(TQ3SubdivisionMethod method)
{
    switch (method) {
    case kQ3SubdivisionMethodConstant:
        return "constant";
    case kQ3SubdivisionMethodWorldSpace:
        return "world-space";
    case kQ3SubdivisionMethodScreenSpace:
        return "screen-space";
    }
    return "unknown";
}

/// What styles and shaders set in a traversal (QD3DStyle.h, QD3DShader.h):
/// the part of the view's graphics state that Push saves and Pop restores
/// besides the transform and the attributes. A style or shader submitted to
/// a view changes its own field and nothing else (Style::apply,
/// Shader::apply). Defaults are QuickDraw 3D's view defaults.
struct DrawState {
    TQ3SubdivisionStyleData subdivision{kQ3SubdivisionMethodScreenSpace, limits::kSubdivisionDefault,
                                        limits::kSubdivisionDefault};
    TQ3BackfacingStyle backfacing = kQ3BackfacingStyleBoth;
    TQ3InterpolationStyle interpolation = kQ3InterpolationStyleVertex;
    TQ3FillStyle fill = kQ3FillStyleFilled;
    TQ3OrientationStyle orientation = kQ3OrientationStyleCounterClockwise;
    /// The highlight style's attribute set (null: none submitted): drawn over
    /// the attributes of geometries whose highlight state attribute is on.
    Ref<AttributeSet> highlight;
    TQ3AntiAliasStyleData antiAlias{kQ3Off, kQ3AntiAliasModeMaskEdges, 1.0f};
    TQ3FogStyleData fog{kQ3Off, kQ3FogModeLinear, 1.0f, 1000.0f, 1.0f, {1.0f, 1.0f, 1.0f, 1.0f}};
    TQ3Boolean receiveShadows = kQ3True;
    TQ3Boolean castShadows = kQ3True;
    unsigned long pickID = 0;
    TQ3PickParts pickParts = kQ3PickPartsObject;
    /// The illumination shader's type (kQ3IlluminationTypePhong, Lambert,
    /// NULL); kQ3ObjectTypeInvalid until one is submitted, which draws
    /// surfaces unlit in their diffuse colours, as QuickDraw 3D does.
    TQ3ObjectType illumination = 0;
    /// The surface shader in force (a texture shader), as it was when it
    /// was submitted: its texture (a q3::Texture, held as a shared object so
    /// that this header needs no shader header), uv transform and
    /// boundaries. A null texture: no surface shader.
    Ref<SharedObject> texture;
    TQ3Matrix3x3 uvTransform{{{1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}};
    TQ3ShaderUVBoundary uBoundary = kQ3ShaderUVBoundaryWrap;
    TQ3ShaderUVBoundary vBoundary = kQ3ShaderUVBoundaryWrap;
};

} // namespace q3
