// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// The API fuzzer's operations on styles, transforms, attribute sets, shaders, lights and elements.

#include "FuzzSession.h"

#include <cstdint>

namespace q3fuzz {

void Session::checkStyle(const char* call, TQ3Status status, bool replaced)
{
    if (status == kQ3Success) {
        require(m_styleValid, call, "accepted a method outside the enumeration");
        require((g_posts.warnings == 1 && g_posts.lastWarning == kQ3WarningParameterOutOfRange) == replaced,
                call, "the substitution warning does not match QD3DStyle.h's rule");
    }
}

void Session::newStyle()
{
    bool replaced = false;
    const TQ3SubdivisionStyleData data = readStyle(replaced);
    const TQ3Object style = OBJECT(Q3SubdivisionStyle_New(&data));
    checkStyle("Q3SubdivisionStyle_New", style != nullptr ? kQ3Success : kQ3Failure, replaced);
    if (style == nullptr)
        return;
    hold(style, Kind::kStyle);
    TQ3SubdivisionStyleData got{};
    STATUS(Q3SubdivisionStyle_GetData(style, &got));
    require(sameBytes(got, m_expectedStyle), "Q3SubdivisionStyle_GetData",
            "does not read back as QD3DStyle.h's substitution rule says");
}

void Session::styleSetGet()
{
    const TQ3Object style = pick(Kind::kStyle);
    bool replaced = false;
    const TQ3SubdivisionStyleData data = readStyle(replaced);
    const bool nullData = m_in.u8() == 0;
    const bool isStyle = holdsKind(style, Kind::kStyle) && m_initialized > 0;
    TQ3SubdivisionStyleData before{};
    unsigned long beforeIndex = 0;
    if (isStyle) {
        STATUS(Q3SubdivisionStyle_GetData(style, &before));
        beforeIndex = editIndex(style);
    }
    const TQ3Status status = STATUS(Q3SubdivisionStyle_SetData(style, nullData ? nullptr : &data));
    checkStyle("Q3SubdivisionStyle_SetData", status, replaced);
    TQ3SubdivisionStyleData got;
    std::memset(&got, 0x5A, sizeof got);
    const TQ3SubdivisionStyleData untouched = got;
    const TQ3Status read = STATUS(Q3SubdivisionStyle_GetData(style, m_in.u8() == 0 ? nullptr : &got));
    if (read == kQ3Failure)
        require(sameBytes(got, untouched), "Q3SubdivisionStyle_GetData", "failed but wrote its output");
    else if (status == kQ3Success)
        require(sameBytes(got, m_expectedStyle), "Q3SubdivisionStyle_SetData", "does not read back");
    else if (isStyle) {
        require(sameBytes(got, before), "Q3SubdivisionStyle_SetData", "failed but changed the style");
        require(editIndex(style) == beforeIndex, "Q3SubdivisionStyle_SetData", "failed but changed the edit index");
    }
}

TQ3Matrix4x4 Session::readMatrix()
{
    TQ3Matrix4x4 m{};
    const std::uint8_t mode = m_in.u8();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            m.value[r][c] = (mode & 1) ? m_in.value() : (r == c ? 1.0f : 0.0f);
    if (!(mode & 1))
        for (int n = mode >> 5; n > 0; --n)
            m.value[m_in.u8() % 4][m_in.u8() % 4] = m_in.value();
    return m;
}

void Session::newTransform()
{
    TQ3Object transform = nullptr;
    switch (m_in.u8() % 6) {
    case 0: {
        const TQ3Matrix4x4 m = readMatrix();
        transform = OBJECT(Q3MatrixTransform_New(m_in.u8() == 0 ? nullptr : &m));
        break;
    }
    case 1: {
        const TQ3Vector3D v = vector3();
        transform = OBJECT(Q3TranslateTransform_New(m_in.u8() == 0 ? nullptr : &v));
        break;
    }
    case 2: {
        const TQ3Vector3D v = vector3();
        transform = OBJECT(Q3ScaleTransform_New(m_in.u8() == 0 ? nullptr : &v));
        break;
    }
    case 3: {
        TQ3RotateTransformData data{};
        setRaw(data.axis, enumValue(3));
        data.radians = m_in.value();
        transform = OBJECT(Q3RotateTransform_New(m_in.u8() == 0 ? nullptr : &data));
        break;
    }
    case 4:
        transform = OBJECT(Q3ResetTransform_New());
        break;
    default: {
        // Q3's matrix helpers feed the transform, as an application's would.
        TQ3Matrix4x4 m{};
        const TQ3Point3D origin = point3();
        const TQ3Vector3D axis = vector3();
        const float angle = m_in.value();
        begin();
        const TQ3Matrix4x4* set = Q3Matrix4x4_SetRotateAboutAxis(&m, &origin, &axis, angle);
        checkPosted("Q3Matrix4x4_SetRotateAboutAxis", set == nullptr);
        transform = OBJECT(Q3MatrixTransform_New(&m));
        break;
    }
    }
    if (transform != nullptr)
        hold(transform, Kind::kTransform);
}

void Session::attributeSet()
{
    TQ3Object set = nullptr;
    if (m_in.u8() < 64) {
        set = OBJECT(Q3AttributeSet_New());
        if (set == nullptr)
            return;
        hold(set, Kind::kAttributeSet);
    } else {
        set = pick(Kind::kAttributeSet);
    }
    for (int n = 1 + m_in.u8() % 4; n > 0; --n) {
        const std::uint8_t which = m_in.u8();
        const TQ3AttributeType type = which < 240 ? TQ3AttributeType(which % 14) : TQ3AttributeType(m_in.u32());
        // Large enough for any attribute's C type (TQ3Tangent2D is 24 bytes).
        float data[8];
        for (float& f : data)
            f = m_in.value();
        if (type == kQ3AttributeTypeHighlightState) {
            const std::int32_t raw = enumValue(2);
            std::memcpy(data, &raw, sizeof raw);
        }
        const bool nullData = m_in.u8() == 0;
        // A surface shader is passed as a handle, read back as a new one.
        const auto releaseShader = [&](TQ3Status status, const float* out) {
            if (status == kQ3Success && type == kQ3AttributeTypeSurfaceShader && !nullData) {
                TQ3Object shader;
                std::memcpy(&shader, out, sizeof shader);
                Q3Object_Dispose(shader);
            }
        };
        switch (m_in.u8() % 10) {
        case 0:
            STATUS(Q3AttributeSet_Add(set, type, nullData ? nullptr : data));
            break;
        case 1: {
            float out[8];
            releaseShader(STATUS(Q3AttributeSet_Get(set, type, nullData ? nullptr : out)), out);
            break;
        }
        case 2:
            QUERY(Q3AttributeSet_Contains(set, type), kQ3False);
            break;
        case 3:
            STATUS(Q3AttributeSet_Clear(set, type));
            break;
        case 4: {
            TQ3AttributeType next = type;
            STATUS(Q3AttributeSet_GetNextAttributeType(set, nullData ? nullptr : &next));
            break;
        }
        case 5:
            STATUS(Q3AttributeSet_Inherit(pick(Kind::kAttributeSet), pick(Kind::kAttributeSet), set));
            break;
        case 6: {
            // The surface shader attribute: a texture shader is not among
            // the fuzzer's objects, so this tries what must be refused.
            TQ3Object shader = pick(Kind::kShader);
            STATUS(Q3AttributeSet_Add(set, kQ3AttributeTypeSurfaceShader, nullData ? nullptr : &shader));
            break;
        }
        case 7: {
            // The generic set calls on the same set (an attribute set is a set).
            float out[8];
            STATUS(Q3Set_Add(set, type, nullData ? nullptr : data));
            releaseShader(STATUS(Q3Set_Get(set, type, nullData ? nullptr : out)), out);
            QUERY(Q3Set_Contains(set, type), kQ3False);
            TQ3ElementType next = type;
            STATUS(Q3Set_GetNextElementType(set, nullData ? nullptr : &next));
            break;
        }
        case 8:
            STATUS(Q3Set_Clear(set, type));
            break;
        default:
            STATUS(Q3AttributeSet_Empty(set));
            break;
        }
    }
}

void Session::stylesShadersLights()
{
    // A held style, shader or light's state through its getters, as
    // bytes (field by field: TQ3AntiAliasStyleData has padding); empty
    // for anything else.
    auto snapshot = [&](TQ3Object object) {
        std::vector<unsigned char> bytes;
        auto add = [&](const auto& value) {
            const auto* p = reinterpret_cast<const unsigned char*>(&value);
            bytes.insert(bytes.end(), p, p + sizeof value);
        };
        const bool ours = holdsKind(object, Kind::kOtherStyle) || holdsKind(object, Kind::kShader) ||
                          holdsKind(object, Kind::kLight);
        if (!ours || m_initialized == 0)
            return bytes;
        auto read = [&](auto get, auto value) {
            if (STATUS(get(object, &value)) != kQ3Success)
                die("snapshot", "a getter failed on a held object of its kind");
            add(value);
        };
        switch (QUERY(Q3Object_GetLeafType(object), TQ3ObjectType{kQ3ObjectTypeInvalid})) {
        case kQ3StyleTypePickID: read(Q3PickIDStyle_Get, 0UL); break;
        case kQ3StyleTypePickParts: read(Q3PickPartsStyle_Get, TQ3PickParts{}); break;
        case kQ3StyleTypeCastShadows: read(Q3CastShadowsStyle_Get, kQ3False); break;
        case kQ3StyleTypeReceiveShadows: read(Q3ReceiveShadowsStyle_Get, kQ3False); break;
        case kQ3StyleTypeFill: read(Q3FillStyle_Get, kQ3FillStyleFilled); break;
        case kQ3StyleTypeBackfacing: read(Q3BackfacingStyle_Get, kQ3BackfacingStyleBoth); break;
        case kQ3StyleTypeInterpolation: read(Q3InterpolationStyle_Get, kQ3InterpolationStyleNone); break;
        case kQ3StyleTypeOrientation: read(Q3OrientationStyle_Get, kQ3OrientationStyleClockwise); break;
        case kQ3StyleTypeFog: read(Q3FogStyle_GetData, TQ3FogStyleData{}); break;
        case kQ3StyleTypeAntiAlias: {
            TQ3AntiAliasStyleData data{};
            STATUS(Q3AntiAliasStyle_GetData(object, &data));
            add(data.state), add(data.mode), add(data.quality);
            break;
        }
        case kQ3StyleTypeHighlight: {
            TQ3AttributeSet set = nullptr;
            STATUS(Q3HighlightStyle_Get(object, &set));
            add(set);
            if (set != nullptr)
                STATUS(Q3Object_Dispose(set));
            break;
        }
        case kQ3LightTypeAmbient: read(Q3AmbientLight_GetData, TQ3LightData{}); break;
        case kQ3LightTypeDirectional: read(Q3DirectionalLight_GetData, TQ3DirectionalLightData{}); break;
        case kQ3LightTypePoint: read(Q3PointLight_GetData, TQ3PointLightData{}); break;
        case kQ3LightTypeSpot: read(Q3SpotLight_GetData, TQ3SpotLightData{}); break;
        default: // an illumination shader
            read(Q3Shader_GetUVTransform, TQ3Matrix3x3{});
            read(Q3Shader_GetUBoundary, kQ3ShaderUVBoundaryWrap);
            read(Q3Shader_GetVBoundary, kQ3ShaderUVBoundaryWrap);
            break;
        }
        return bytes;
    };
    // Runs one edit. `valid`: 1 or 0 when the handle is known to be of the
    // call's kind and the values do or do not obey the rules, -1 when the
    // outcome is not predicted. `expected`: the state a success must leave
    // (empty: not checked).
    auto edit = [&](const char* call, TQ3Object object, int valid, const std::vector<unsigned char>& expected,
                    auto run) {
        const std::vector<unsigned char> before = snapshot(object);
        const unsigned long index = before.empty() ? 0 : editIndex(object);
        begin();
        const TQ3Status status = checkStatus(call, run());
        if (valid >= 0 && m_initialized > 0)
            require((status == kQ3Success) == (valid == 1), call, "disagrees with the header's rules");
        if (before.empty())
            return status;
        if (status == kQ3Success) {
            require(editIndex(object) != index, call, "succeeded without changing the edit index");
            require(expected.empty() || snapshot(object) == expected, call, "does not read back");
        } else {
            require(editIndex(object) == index, call, "failed but changed the edit index");
            require(snapshot(object) == before, call, "failed but changed the object");
        }
        return status;
    };
    auto bytesOf = [](const auto& value) {
        const auto* p = reinterpret_cast<const unsigned char*>(&value);
        return std::vector<unsigned char>(p, p + sizeof value);
    };
    const std::uint8_t action = m_in.u8() % 5;
    if (action == 0) {
        // A style: New, immediate Submit or Set, with one value.
        static const TQ3ObjectType kTypes[] = {kQ3StyleTypeFill,        kQ3StyleTypeBackfacing,
                                               kQ3StyleTypeInterpolation, kQ3StyleTypeOrientation,
                                               kQ3StyleTypeCastShadows, kQ3StyleTypeReceiveShadows,
                                               kQ3StyleTypePickID,      kQ3StyleTypePickParts,
                                               kQ3StyleTypeAntiAlias,   kQ3StyleTypeFog,
                                               kQ3StyleTypeHighlight};
        const int which = m_in.u8() % 11;
        static const int kLast[] = {2, 2, 2, 1, 1, 1};
        const std::int32_t raw = which < 6 ? enumValue(kLast[which] + 1) : 0;
        const unsigned long word = which == 6 ? m_in.u32() : which == 7 ? (unsigned long)enumValue(8) : 0;
        TQ3AntiAliasStyleData antiAlias{};
        TQ3FogStyleData fog{};
        std::int32_t state = enumValue(2), mode = 0;
        if (which == 8) {
            setRaw(antiAlias.state, state);
            antiAlias.mode = (unsigned long)enumValue(4);
            antiAlias.quality = m_in.value();
        } else if (which == 9) {
            mode = enumValue(4);
            setRaw(fog.state, state);
            setRaw(fog.mode, mode);
            fog.fogStart = m_in.value();
            fog.fogEnd = m_in.value();
            fog.density = m_in.value();
            fog.color = {m_in.value(), m_in.value(), m_in.value(), m_in.value()};
        }
        const TQ3Object set = which == 10 ? pick(Kind::kAttributeSet) : nullptr;
        const bool nullData = m_in.u8() == 0;
        bool obeys = true;
        std::vector<unsigned char> expected;
        if (which < 4)
            obeys = raw >= 0 && raw <= kLast[which], expected = bytesOf(raw);
        else if (which < 6)
            expected = bytesOf(std::int32_t(raw != 0));
        else if (which == 6)
            expected = bytesOf(word);
        else if (which == 7)
            obeys = (word & ~7UL) == 0, expected = bytesOf(word);
        else if (which == 8) {
            obeys = (state == 0 || state == 1) && (antiAlias.mode & ~3UL) == 0 &&
                    std::isfinite(antiAlias.quality) && antiAlias.quality >= 0.0f && antiAlias.quality <= 1.0f;
            expected = bytesOf(antiAlias.state);
            for (const auto& part : {bytesOf(antiAlias.mode), bytesOf(antiAlias.quality)})
                expected.insert(expected.end(), part.begin(), part.end());
        } else if (which == 9) {
            obeys = (state == 0 || state == 1) && mode >= 0 && mode <= 3 &&
                    allFinite({fog.fogStart, fog.fogEnd, fog.density, fog.color.a, fog.color.r, fog.color.g,
                               fog.color.b}) &&
                    fog.density >= 0.0f && !(state == 1 && mode == 0 && !(fog.fogStart < fog.fogEnd));
            expected = bytesOf(fog);
        } else {
            obeys = set == nullptr || holdsKind(set, Kind::kAttributeSet), expected = bytesOf(set);
        }
        auto create = [&]() -> TQ3Object {
            switch (which) {
            case 6: return Q3PickIDStyle_New(word);
            case 7: return Q3PickPartsStyle_New(word);
            case 8: return Q3AntiAliasStyle_New(nullData ? nullptr : &antiAlias);
            case 9: return Q3FogStyle_New(nullData ? nullptr : &fog);
            case 10: return Q3HighlightStyle_New(set);
            default: return q3fuzz_EnumStyle_New(which, raw);
            }
        };
        const std::uint8_t path = m_in.u8() % 3;
        if (path == 0) {
            begin();
            const TQ3Object style = checkObject("a style's _New", create());
            if (m_initialized > 0)
                require((style != nullptr) == (obeys && !(nullData && (which == 8 || which == 9))),
                        "a style's _New", "disagrees with QD3DStyle.h's rules");
            if (style == nullptr)
                return;
            hold(style, Kind::kOtherStyle);
            require(snapshot(style) == expected, "a style's _New", "does not read back");
        } else if (path == 1) {
            const TQ3Object view = pick(Kind::kView);
            begin();
            switch (which) {
            case 6: checkStatus("Q3PickIDStyle_Submit", Q3PickIDStyle_Submit(word, view)); break;
            case 7: checkStatus("Q3PickPartsStyle_Submit", Q3PickPartsStyle_Submit(word, view)); break;
            case 8: checkStatus("Q3AntiAliasStyle_Submit", Q3AntiAliasStyle_Submit(&antiAlias, view)); break;
            case 9: checkStatus("Q3FogStyle_Submit", Q3FogStyle_Submit(&fog, view)); break;
            case 10: checkStatus("Q3HighlightStyle_Submit", Q3HighlightStyle_Submit(set, view)); break;
            default: checkStatus("a style's _Submit", q3fuzz_EnumStyle_Submit(which, raw, view)); break;
            }
        } else {
            const TQ3Object style = pick(Kind::kOtherStyle);
            const bool sameKind = holdsKind(style, Kind::kOtherStyle) && m_initialized > 0 &&
                                  QUERY(Q3Style_GetType(style), TQ3ObjectType{0}) == kTypes[which];
            const int valid = sameKind ? int(obeys && !(nullData && (which == 8 || which == 9))) : -1;
            edit("a style's _Set", style, valid, expected, [&] {
                switch (which) {
                case 6: return Q3PickIDStyle_Set(style, word);
                case 7: return Q3PickPartsStyle_Set(style, word);
                case 8: return Q3AntiAliasStyle_SetData(style, nullData ? nullptr : &antiAlias);
                case 9: return Q3FogStyle_SetData(style, nullData ? nullptr : &fog);
                case 10: return Q3HighlightStyle_Set(style, set);
                default: return q3fuzz_EnumStyle_Set(which, style, raw);
                }
            });
        }
    } else if (action == 1) {
        // Calls on any style, shader or light: types, retained submit,
        // highlight Get, a light's single getters.
        static const Kind kKinds[] = {Kind::kOtherStyle, Kind::kShader, Kind::kLight};
        const TQ3Object object = pick(kKinds[m_in.u8() % 3]);
        const TQ3Object view = pick(Kind::kView);
        TQ3AttributeSet set = nullptr;
        const bool nullOut = m_in.u8() == 0;
        float value = 0.5f;
        switch (m_in.u8() % 9) {
        case 6: QUERY(Q3Light_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
        case 7:
            if (STATUS(Q3SpotLight_GetOuterAngle(object, nullOut ? nullptr : &value)) != kQ3Success)
                require(value == 0.5f, "Q3SpotLight_GetOuterAngle", "failed but wrote its output");
            break;
        case 8:
            if (STATUS(Q3Light_GetBrightness(object, nullOut ? nullptr : &value)) != kQ3Success)
                require(value == 0.5f, "Q3Light_GetBrightness", "failed but wrote its output");
            break;
        case 0: QUERY(Q3Style_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
        case 1: QUERY(Q3Shader_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
        case 2: QUERY(Q3IlluminationShader_GetType(object), TQ3ObjectType{kQ3ObjectTypeInvalid}); break;
        case 3: STATUS(Q3Style_Submit(object, view)); break;
        case 4: STATUS(Q3Shader_Submit(object, view)); break;
        default:
            STATUS(Q3HighlightStyle_Get(object, nullOut ? nullptr : &set));
            if (set != nullptr)
                hold(set, Kind::kAttributeSet);
            break;
        }
    } else if (action == 2) {
        // Illumination shaders and the uv calls every shader has.
        const std::uint8_t call = m_in.u8() % 4;
        if (call == 0) {
            static TQ3ShaderObject (*const kNew[])() = {Q3PhongIllumination_New, Q3LambertIllumination_New,
                                                        Q3NULLIllumination_New};
            const TQ3Object shader = OBJECT(kNew[m_in.u8() % 3]());
            if (shader != nullptr)
                hold(shader, Kind::kShader);
            return;
        }
        const TQ3Object shader = pick(Kind::kShader);
        const bool ours = holdsKind(shader, Kind::kShader) && m_initialized > 0;
        const bool nullArg = m_in.u8() == 0;
        if (call == 1) {
            TQ3Matrix3x3 m{};
            for (auto& row : m.value)
                for (float& v : row)
                    v = (m_in.u8() & 1) ? m_in.value() : 0.0f;
            bool finite = true;
            for (auto& row : m.value)
                for (float v : row)
                    finite = finite && std::isfinite(v);
            std::vector<unsigned char> expected = bytesOf(m);
            if (ours) {
                const std::vector<unsigned char> now = snapshot(shader);
                expected.insert(expected.end(), now.end() - 2 * sizeof(TQ3ShaderUVBoundary), now.end());
            }
            edit("Q3Shader_SetUVTransform", shader, ours ? int(finite && !nullArg) : -1, expected,
                 [&] { return Q3Shader_SetUVTransform(shader, nullArg ? nullptr : &m); });
            TQ3Matrix3x3 out = m;
            if (STATUS(Q3Shader_GetUVTransform(shader, m_in.u8() == 0 ? nullptr : &out)) != kQ3Success)
                require(sameBytes(out, m), "Q3Shader_GetUVTransform", "failed but wrote its output");
        } else if (call == 2) {
            const bool v = m_in.u8() & 1;
            const std::int32_t raw = enumValue(2);
            edit(v ? "Q3Shader_SetVBoundary" : "Q3Shader_SetUBoundary", shader,
                 ours ? int(raw == 0 || raw == 1) : -1, {},
                 [&] { return q3fuzz_SetEnumField(v ? 8 : 7, shader, raw); });
        } else {
            TQ3ShaderUVBoundary out = kQ3ShaderUVBoundaryClamp;
            TQ3ShaderUVBoundary* where = nullArg ? nullptr : &out;
            const TQ3Status status = (m_in.u8() & 1) ? STATUS(Q3Shader_GetUBoundary(shader, where))
                                                     : STATUS(Q3Shader_GetVBoundary(shader, where));
            if (status != kQ3Success)
                require(out == kQ3ShaderUVBoundaryClamp, "Q3Shader_GetUBoundary", "failed but wrote its output");
        }
    } else {
        // Lights: New or SetData of a kind with any values (action 3), or
        // one value through its own setter (action 4).
        AnyLight l;
        l.kind = m_in.u8() % 4;
        TQ3SpotLightData& d = l.data;
        l.isOn = enumValue(1);
        d.lightData.brightness = m_in.value();
        d.lightData.color = {m_in.value(), m_in.value(), m_in.value()};
        l.castsShadows = enumValue(1);
        l.attenuation = enumValue(3);
        d.location = point3();
        d.direction = vector3();
        d.hotAngle = m_in.value();
        d.outerAngle = m_in.value();
        l.fallOff = enumValue(4);
        const bool nullData = m_in.u8() == 0;
        const LightStructures given = lightStructures(l, false);
        static const TQ3ObjectType kKinds[] = {kQ3LightTypeAmbient, kQ3LightTypeDirectional, kQ3LightTypePoint,
                                               kQ3LightTypeSpot};
        const TQ3Object light = pick(Kind::kLight);
        const bool ours = holdsKind(light, Kind::kLight) && m_initialized > 0;
        // The held light's current values.
        AnyLight now;
        if (ours) {
            const TQ3ObjectType type = QUERY(Q3Light_GetType(light), TQ3ObjectType{0});
            now.kind = int(std::find(kKinds, kKinds + 4, type) - kKinds);
            const std::vector<unsigned char> bytes = snapshot(light);
            LightStructures held{};
            void* into[] = {&held.common, &held.directional, &held.point, &held.spot};
            std::memcpy(into[now.kind], bytes.data(), bytes.size());
            now = anyLight(now.kind, held);
        }
        if (action == 3 && (m_in.u8() & 1)) {
            begin();
            TQ3Object created = nullptr;
            switch (l.kind) {
            case 0: created = Q3AmbientLight_New(nullData ? nullptr : &given.common); break;
            case 1: created = Q3DirectionalLight_New(nullData ? nullptr : &given.directional); break;
            case 2: created = Q3PointLight_New(nullData ? nullptr : &given.point); break;
            default: created = Q3SpotLight_New(nullData ? nullptr : &given.spot); break;
            }
            checkObject("a light's _New", created);
            if (m_initialized > 0)
                require((created != nullptr) == (!nullData && lightObeysRules(l)), "a light's _New",
                        "disagrees with QD3DLight.h's rules");
            if (created != nullptr) {
                hold(created, Kind::kLight);
                require(snapshot(created) == lightBytes(l), "a light's _New", "does not read back");
            }
        } else if (action == 3) {
            const int valid = ours && now.kind == l.kind ? int(!nullData && lightObeysRules(l)) : -1;
            edit("a light's _SetData", light, valid, lightBytes(l), [&] {
                switch (l.kind) {
                case 0: return Q3AmbientLight_SetData(light, nullData ? nullptr : &given.common);
                case 1: return Q3DirectionalLight_SetData(light, nullData ? nullptr : &given.directional);
                case 2: return Q3PointLight_SetData(light, nullData ? nullptr : &given.point);
                default: return Q3SpotLight_SetData(light, nullData ? nullptr : &given.spot);
                }
            });
        } else {
            // One setter, the kind it takes (-1: any light), and what it
            // does to the light's values.
            const int call = m_in.u8() % 16;
            static const int kTakes[] = {-1, -1, -1, -1, 1, 1, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3};
            static const bool kPointer[] = {false, false, true, true, false, true, false, false,
                                            true,  false, false, true, true, false, false, false};
            AnyLight next = now;
            switch (call) {
            case 0: next.isOn = l.isOn; break;
            case 1: next.data.lightData.brightness = d.lightData.brightness; break;
            case 2: next.data.lightData.color = d.lightData.color; break;
            case 3: next.data.lightData = d.lightData, next.isOn = l.isOn; break;
            case 4: case 6: case 9: next.castsShadows = l.castsShadows; break;
            case 5: case 12: next.data.direction = d.direction; break;
            case 7: case 10: next.attenuation = l.attenuation; break;
            case 8: case 11: next.data.location = d.location; break;
            case 13: next.data.hotAngle = d.hotAngle; break;
            case 14: next.data.outerAngle = d.outerAngle; break;
            default: next.fallOff = l.fallOff; break;
            }
            const bool nullArg = nullData && kPointer[call];
            const bool fits = ours && (kTakes[call] < 0 || kTakes[call] == now.kind);
            edit("a light's setter", light, fits ? int(!nullArg && lightObeysRules(next)) : -1,
                 fits ? lightBytes(next) : std::vector<unsigned char>{}, [&] {
                     const TQ3ColorRGB* color = nullArg ? nullptr : &d.lightData.color;
                     const TQ3Vector3D* direction = nullArg ? nullptr : &d.direction;
                     const TQ3Point3D* location = nullArg ? nullptr : &d.location;
                     switch (call) {
                     case 0: return q3fuzz_SetEnumField(0, light, l.isOn);
                     case 1: return Q3Light_SetBrightness(light, d.lightData.brightness);
                     case 2: return Q3Light_SetColor(light, color);
                     case 3: return Q3Light_SetData(light, nullArg ? nullptr : &given.common);
                     case 4: return q3fuzz_SetEnumField(1, light, l.castsShadows);
                     case 5: return Q3DirectionalLight_SetDirection(light, direction);
                     case 6: return q3fuzz_SetEnumField(2, light, l.castsShadows);
                     case 7: return q3fuzz_SetEnumField(3, light, l.attenuation);
                     case 8: return Q3PointLight_SetLocation(light, location);
                     case 9: return q3fuzz_SetEnumField(4, light, l.castsShadows);
                     case 10: return q3fuzz_SetEnumField(5, light, l.attenuation);
                     case 11: return Q3SpotLight_SetLocation(light, location);
                     case 12: return Q3SpotLight_SetDirection(light, direction);
                     case 13: return Q3SpotLight_SetHotAngle(light, d.hotAngle);
                     case 14: return Q3SpotLight_SetOuterAngle(light, d.outerAngle);
                     default: return q3fuzz_SetEnumField(6, light, l.fallOff);
                     }
                 });
        }
    }
}

void Session::elements()
{
    const TQ3Object target = pick(static_cast<Kind>(m_in.u8() % kKindCount));
    const std::uint8_t which = m_in.u8();
    const TQ3ElementType type = which < 200 ? TQ3ElementType(which % 40) : TQ3ElementType(std::int32_t(m_in.u32()));
    // Large enough for any element's C type; a handle read from it is
    // checked by Q3 before use.
    float data[8];
    for (float& f : data)
        f = m_in.value();
    const bool handleType = type == kQ3AttributeTypeSurfaceShader || type == kQ3ElementTypeSet;
    switch (m_in.u8() % 12) {
    case 0:
        STATUS(Q3Object_AddElement(target, type, m_in.u8() == 0 ? nullptr : data));
        break;
    case 1:
        STATUS(Q3Shape_AddElement(target, type, data));
        break;
    case 2: {
        float out[8] = {};
        if (STATUS(Q3Object_GetElement(target, type, out)) == kQ3Success && handleType) {
            TQ3Object got;
            std::memcpy(&got, out, sizeof got);
            Q3Object_Dispose(got);
        }
        break;
    }
    case 3:
        QUERY(Q3Shape_ContainsElement(target, type), kQ3False);
        break;
    case 4: {
        TQ3ElementType next = m_in.u8() < 200 ? TQ3ElementType(kQ3ElementTypeNone) : type;
        for (int i = 0; i < 40; ++i)
            if (STATUS(Q3Object_GetNextElementType(target, &next)) != kQ3Success || next == kQ3ElementTypeNone)
                break;
        break;
    }
    case 5:
        STATUS(Q3Shape_ClearElement(target, type));
        break;
    case 6:
        STATUS(m_in.u8() < 128 ? Q3Object_EmptyElements(target) : Q3Shape_EmptyElements(target));
        break;
    case 7: {
        char name[12];
        for (char& c : name)
            c = static_cast<char>(1 + m_in.u8() % 255);
        name[sizeof name - 1] = '\0';
        STATUS(CENameElement_SetData(target, m_in.u8() < 32 ? nullptr : name));
        break;
    }
    case 8: {
        char* got = nullptr;
        if (STATUS(CENameElement_GetData(target, &got)) == kQ3Success)
            STATUS(CENameElement_EmptyData(&got));
        break;
    }
    // Outside a custom class's traverse method both must fail, whatever the
    // target (QD3DIO.h).
    case 9:
        STATUS(Q3XView_SubmitWriteData(target, m_in.u32(), data, nullptr));
        break;
    case 10: {
        // The class is looked up first, on its own: a lookup that posts (an
        // unknown type, or after Q3Exit) must not count as the submit's post.
        const TQ3XObjectClass objectClass = Q3XObjectHierarchy_FindClassByType(type);
        STATUS(Q3XView_SubmitSubObjectData(target, objectClass, m_in.u32(), data, nullptr));
        break;
    }
    // A class answering kQ3XMethodTypeObjectFileVersion with any version:
    // one newer than 1.6 is refused, any other registers (QD3DIO.h).
    case 11: {
        static thread_local TQ3FileVersion s_version = 0;
        s_version = m_in.u8() < 128 ? TQ3FileVersion(m_in.u32()) : TQ3FileVersion(Q3FileVersion(1, m_in.u8() % 9));
        const TQ3XMetaHandler handler = [](TQ3XMethodType method) -> TQ3XFunctionPointer {
            return method == kQ3XMethodTypeObjectFileVersion
                       ? reinterpret_cast<TQ3XFunctionPointer>(static_cast<std::uintptr_t>(s_version))
                       : nullptr;
        };
        TQ3ObjectType registered = 0;
        char name[] = "Fuzz:Versioned";
        TQ3XObjectClass made = POINTER(
            Q3XObjectHierarchy_RegisterClass(kQ3ObjectTypeShared, &registered, name, handler, nullptr, 0, 4));
        // (Not initialized, every registration fails: Q3Exit's operation.)
        require((made == nullptr) == (m_initialized == 0 || s_version > kQ3FileVersionCurrent),
                "Q3XObjectHierarchy_RegisterClass",
                "a class's file version newer than 1.6 must be refused, any other accepted");
        if (made != nullptr)
            STATUS(Q3XObjectHierarchy_UnregisterClass(made));
        break;
    }
    }
}

} // namespace q3fuzz
