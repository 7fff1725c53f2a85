// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Styles, illumination shaders, lights and transforms (3D Metafile
// Reference, "Style objects", "Shader objects", "Light objects",
// "Transform objects"). Enumerations are words in text files and 32-bit
// values in binary ones. A light's common data (on, brightness, colour) is a
// LightData subobject of the light's container. Every object read is built
// through its class's own checks.

#include "io/ClassIO.h"

#include "light/AmbientLight.h"
#include "light/DirectionalLight.h"
#include "light/PointLight.h"
#include "light/SpotLight.h"
#include "shader/IlluminationShaders.h"
#include "style/HighlightStyle.h"
#include "style/SubdivisionStyle.h"
#include "style/ValueStyles.h"
#include "view/Transform.h"

namespace q3::io {
namespace {

using Names = std::vector<std::pair<const char*, std::uint32_t>>;

const Names kBoolean = {{"False", kQ3False}, {"True", kQ3True}};
// Q3 writes "BothSides"; files written by other tools (Quesa's test models
// among them) say "Both", which reads the same.
const Names kBackfacing = {{"BothSides", kQ3BackfacingStyleBoth},
                           {"Remove", kQ3BackfacingStyleRemove},
                           {"Flip", kQ3BackfacingStyleFlip},
                           {"Both", kQ3BackfacingStyleBoth}};
const Names kInterpolation = {{"None", kQ3InterpolationStyleNone},
                              {"Vertex", kQ3InterpolationStyleVertex},
                              {"Pixel", kQ3InterpolationStylePixel}};
const Names kFill = {{"Filled", kQ3FillStyleFilled}, {"Edges", kQ3FillStyleEdges}, {"Points", kQ3FillStylePoints}};
const Names kOrientation = {{"CounterClockwise", kQ3OrientationStyleCounterClockwise},
                            {"Clockwise", kQ3OrientationStyleClockwise}};
const Names kPickParts = {{"Object", kQ3PickPartsObject},
                          {"Face", kQ3PickPartsMaskFace},
                          {"Edge", kQ3PickPartsMaskEdge},
                          {"Vertex", kQ3PickPartsMaskVertex}};
const Names kSubdivision = {{"Constant", kQ3SubdivisionMethodConstant},
                            {"WorldSpace", kQ3SubdivisionMethodWorldSpace},
                            {"ScreenSpace", kQ3SubdivisionMethodScreenSpace}};
const Names kAttenuation = {{"None", kQ3AttenuationTypeNone},
                            {"InverseDistance", kQ3AttenuationTypeInverseDistance},
                            {"InverseDistanceSquared", kQ3AttenuationTypeInverseDistanceSquared}};
const Names kFallOff = {{"None", kQ3FallOffTypeNone},
                        {"Linear", kQ3FallOffTypeLinear},
                        {"Exponential", kQ3FallOffTypeExponential},
                        {"Cosine", kQ3FallOffTypeCosine}};
const Names kAxis = {{"X", kQ3AxisX}, {"Y", kQ3AxisY}, {"Z", kQ3AxisZ}};

// LightData's binary tag is 'lght', as in Apple's own metafile parser (MF3D's
// kMF3DObjLightData), so that lights in binary files written by QuickDraw 3D
// keep their state.
constexpr TQ3ObjectType kTypeLightData = Q3_OBJECT_TYPE('l', 'g', 'h', 't');

// Builds an object from file data through its class's checks.
template <class T, class... Args>
Ref<SharedObject> build(const char* what, Args&&... args)
{
    try {
        return Ref<SharedObject>(makeShared<T>(std::forward<Args>(args)...));
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidMetafileObject, std::string("the file's ") + what + " breaks a rule: " + error.what());
    }
}

// ---- styles whose data is one value ----------------------------------------

template <class Style, const Names* names, bool isFlags = false>
struct ValueStyleIO {
    static Ref<SharedObject> read(ReadContext& context, const Parts& parts)
    {
        DataReader in = context.reader(parts.root);
        std::uint32_t raw = 0;
        if (names == nullptr)
            raw = in.u32();
        else
            raw = isFlags ? in.flags(*names) : in.choice(*names);
        using Value = typename Style::Value;
        return build<Style>("style", static_cast<Value>(raw));
    }
    static void write(WriteContext& context, const Object& object, TQ3ObjectType type, const char* name)
    {
        const auto& style = static_cast<const Style&>(object);
        Encoder& out = context.out();
        out.begin(type, name);
        const auto raw = static_cast<std::uint32_t>(style.value());
        if (names == nullptr)
            out.u32(raw);
        else if (isFlags)
            out.flags(*names, raw);
        else
            out.choice(*names, raw);
        out.end();
    }
};

#define Q3_VALUE_STYLE(Style, names, isFlags, type, name)                                               \
    ClassIO                                                                                             \
    {                                                                                                   \
        type, name, ValueStyleIO<Style, names, isFlags>::read, [](WriteContext& c, const Object& o) { \
            ValueStyleIO<Style, names, isFlags>::write(c, o, type, name);                               \
        }                                                                                               \
    }

Ref<SharedObject> readSubdivision(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3SubdivisionStyleData data{};
    data.method = static_cast<TQ3SubdivisionMethod>(in.choice(kSubdivision));
    if (data.method == kQ3SubdivisionMethodConstant) {
        data.c1 = static_cast<float>(in.u32());
        data.c2 = static_cast<float>(in.u32());
    } else {
        // The format has one length for these methods; Q3 checks c2 too and
        // uses c1 for curves and surfaces alike, so c2 gets the same value.
        data.c1 = in.f32();
        data.c2 = data.c1;
    }
    return build<SubdivisionStyle>("subdivision style", data);
}

void writeSubdivision(WriteContext& context, const Object& object)
{
    const TQ3SubdivisionStyleData& data = static_cast<const SubdivisionStyle&>(object).data();
    Encoder& out = context.out();
    out.begin(kQ3StyleTypeSubdivision, "SubdivisionStyle");
    out.choice(kSubdivision, static_cast<std::uint32_t>(data.method));
    if (data.method == kQ3SubdivisionMethodConstant) {
        out.u32(static_cast<std::uint32_t>(data.c1));
        out.u32(static_cast<std::uint32_t>(data.c2));
    } else {
        out.f32(data.c1);
    }
    out.end();
}

const Names kSwitch = {{"Off", kQ3Off}, {"On", kQ3On}};
const Names kAntiAliasMode = {{"Edges", kQ3AntiAliasModeMaskEdges}, {"Filled", kQ3AntiAliasModeMaskFilled}};
const Names kFogMode = {{"Linear", kQ3FogModeLinear},
                        {"Exponential", kQ3FogModeExponential},
                        {"ExponentialSquared", kQ3FogModeExponentialSquared},
                        {"Alpha", kQ3FogModeAlpha}};

Ref<SharedObject> readAntiAlias(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3AntiAliasStyleData data{};
    data.state = static_cast<TQ3Switch>(in.choice(kSwitch));
    data.mode = in.flags(kAntiAliasMode);
    data.quality = in.f32();
    return build<AntiAliasStyle>("anti-alias style", data);
}

void writeAntiAlias(WriteContext& context, const Object& object)
{
    const TQ3AntiAliasStyleData& data = static_cast<const AntiAliasStyle&>(object).value();
    Encoder& out = context.out();
    out.begin(kQ3StyleTypeAntiAlias, "AntiAliasStyle");
    out.choice(kSwitch, static_cast<std::uint32_t>(data.state));
    out.flags(kAntiAliasMode, static_cast<std::uint32_t>(data.mode));
    out.f32(data.quality);
    out.end();
}

Ref<SharedObject> readFog(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3FogStyleData data{};
    data.state = static_cast<TQ3Switch>(in.choice(kSwitch));
    data.mode = static_cast<TQ3FogMode>(in.choice(kFogMode));
    data.fogStart = in.f32();
    data.fogEnd = in.f32();
    data.density = in.f32();
    data.color.a = in.f32();
    data.color.r = in.f32();
    data.color.g = in.f32();
    data.color.b = in.f32();
    return build<FogStyle>("fog style", data);
}

void writeFog(WriteContext& context, const Object& object)
{
    const TQ3FogStyleData& data = static_cast<const FogStyle&>(object).value();
    Encoder& out = context.out();
    out.begin(kQ3StyleTypeFog, "FogStyle");
    out.choice(kSwitch, static_cast<std::uint32_t>(data.state));
    out.choice(kFogMode, static_cast<std::uint32_t>(data.mode));
    out.f32(data.fogStart);
    out.f32(data.fogEnd);
    out.f32(data.density);
    out.f32(data.color.a);
    out.f32(data.color.r);
    out.f32(data.color.g);
    out.f32(data.color.b);
    out.end();
}

// The highlight style: its attribute set as a subobject.
Ref<SharedObject> readHighlight(ReadContext& context, const Parts& parts)
{
    return build<HighlightStyle>("highlight style", context.attributeSet(parts));
}

void writeHighlight(WriteContext& context, const Object& object)
{
    const Ref<AttributeSet>& set = static_cast<const HighlightStyle&>(object).attributes();
    maybeContainer(context, WriteContext::hasAttributes(set.get()), [&] {
        context.out().begin(kQ3StyleTypeHighlight, "HighlightStyle");
        context.out().end();
        context.attributeSet(set.get());
    });
}

// ---- illumination shaders ------------------------------------------------------

template <class Shader>
Ref<SharedObject> readShader(ReadContext&, const Parts&)
{
    return Ref<SharedObject>(makeShared<Shader>());
}

template <TQ3ObjectType type>
void writeEmpty(WriteContext& context, const char* name)
{
    context.out().begin(type, name);
    context.out().end();
}

// ---- lights ----------------------------------------------------------------------

TQ3LightData readLightData(ReadContext& context, const Parts& parts)
{
    TQ3LightData data{kQ3True, 1.0f, {1, 1, 1}};
    const Node* node = parts.find(kTypeLightData);
    if (node == nullptr)
        return data;
    DataReader in = context.reader(*node);
    data.isOn = static_cast<TQ3Boolean>(in.choice(kBoolean));
    data.brightness = in.f32();
    data.color = in.color();
    return data;
}

void writeLightData(Encoder& out, const TQ3LightData& data)
{
    out.begin(kTypeLightData, "LightData");
    out.choice(kBoolean, data.isOn != kQ3False ? kQ3True : kQ3False);
    out.f32(data.brightness);
    out.color(data.color);
    out.end();
}

Ref<SharedObject> readAmbient(ReadContext& context, const Parts& parts)
{
    return build<AmbientLight>("ambient light", readLightData(context, parts));
}

void writeAmbient(WriteContext& context, const Object& object)
{
    const TQ3LightData& data = static_cast<const AmbientLight&>(object).data();
    maybeContainer(context, true, [&] {
        writeEmpty<kQ3LightTypeAmbient>(context, "AmbientLight");
        writeLightData(context.out(), data);
    });
}

Ref<SharedObject> readDirectional(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    TQ3DirectionalLightData data{};
    data.direction = in.vector3D();
    data.castsShadows = static_cast<TQ3Boolean>(in.choice(kBoolean));
    data.lightData = readLightData(context, parts);
    return build<DirectionalLight>("directional light", data);
}

void writeDirectional(WriteContext& context, const Object& object)
{
    const TQ3DirectionalLightData& data = static_cast<const DirectionalLight&>(object).data();
    maybeContainer(context, true, [&] {
        Encoder& out = context.out();
        out.begin(kQ3LightTypeDirectional, "DirectionalLight");
        out.vector3D(data.direction);
        out.choice(kBoolean, data.castsShadows != kQ3False ? kQ3True : kQ3False);
        out.end();
        writeLightData(out, data.lightData);
    });
}

// A point or spot light's attenuation. QuickDraw 3D's lights hold a
// TQ3AttenuationType, written as one enumeration; Apple's 1995 metafile
// parser (MF3D) and the QD3D 1.5.4 book's point light example hold three
// Float32 coefficients c0 c1 c2 (1 / (c0 + c1 d + c2 d^2)) instead. The two
// forms differ in size, so the data left tells them apart: exactly room for
// the three coefficients and `bytesAfter` bytes (binary) or `tokensAfter`
// tokens (text) after them reads the coefficients, taken as the nearest
// QuickDraw 3D type (a squared term: InverseDistanceSquared; else a linear
// one: InverseDistance; else None). Negative coefficients are refused.
TQ3AttenuationType readAttenuation(DataReader& in, bool text, std::size_t bytesAfter, std::size_t tokensAfter)
{
    if (in.remaining() != (text ? 3 + tokensAfter : 12 + bytesAfter))
        return static_cast<TQ3AttenuationType>(in.choice(kAttenuation));
    float c[3];
    for (float& coefficient : c) {
        coefficient = in.f32();
        if (coefficient < 0)
            fail(kQ3ErrorInvalidMetafileObject,
                 "a light's attenuation coefficient " + std::to_string(coefficient) + " is negative");
    }
    if (c[2] > 0)
        return kQ3AttenuationTypeInverseDistanceSquared;
    return c[1] > 0 ? kQ3AttenuationTypeInverseDistance : kQ3AttenuationTypeNone;
}

Ref<SharedObject> readPointLight(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const bool text = context.file().encoding == Encoding::kText;
    TQ3PointLightData data{};
    data.location = in.point3D();
    data.attenuation = readAttenuation(in, text, 4, 1); // castsShadows follows
    data.castsShadows = static_cast<TQ3Boolean>(in.choice(kBoolean));
    data.lightData = readLightData(context, parts);
    return build<PointLight>("point light", data);
}

void writePointLight(WriteContext& context, const Object& object)
{
    const TQ3PointLightData& data = static_cast<const PointLight&>(object).data();
    maybeContainer(context, true, [&] {
        Encoder& out = context.out();
        out.begin(kQ3LightTypePoint, "PointLight");
        out.point3D(data.location);
        out.choice(kAttenuation, static_cast<std::uint32_t>(data.attenuation));
        out.choice(kBoolean, data.castsShadows != kQ3False ? kQ3True : kQ3False);
        out.end();
        writeLightData(out, data.lightData);
    });
}

Ref<SharedObject> readSpotLight(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    const bool text = context.file().encoding == Encoding::kText;
    TQ3SpotLightData data{};
    data.location = in.point3D();
    data.direction = in.vector3D();
    data.castsShadows = static_cast<TQ3Boolean>(in.choice(kBoolean));
    data.attenuation = readAttenuation(in, text, 12, 3); // hotAngle, outerAngle, fallOff follow
    data.hotAngle = in.f32();
    data.outerAngle = in.f32();
    data.fallOff = static_cast<TQ3FallOffType>(in.choice(kFallOff));
    data.lightData = readLightData(context, parts);
    return build<SpotLight>("spot light", data);
}

void writeSpotLight(WriteContext& context, const Object& object)
{
    const TQ3SpotLightData& data = static_cast<const SpotLight&>(object).data();
    maybeContainer(context, true, [&] {
        Encoder& out = context.out();
        out.begin(kQ3LightTypeSpot, "SpotLight");
        out.point3D(data.location);
        out.vector3D(data.direction);
        out.choice(kBoolean, data.castsShadows != kQ3False ? kQ3True : kQ3False);
        out.choice(kAttenuation, static_cast<std::uint32_t>(data.attenuation));
        out.f32(data.hotAngle);
        out.f32(data.outerAngle);
        out.choice(kFallOff, static_cast<std::uint32_t>(data.fallOff));
        out.end();
        writeLightData(out, data.lightData);
    });
}

// ---- transforms ------------------------------------------------------------------

// The value of each transform but reset, in the 3D Metafile Reference's
// order of its fields.

void readValue(DataReader& in, TQ3Matrix4x4& m)
{
    for (auto& row : m.value)
        for (float& v : row)
            v = in.f32();
}

void writeValue(Encoder& out, const TQ3Matrix4x4& m)
{
    for (const auto& row : m.value)
        for (float v : row)
            out.f32(v);
}

// Translate and Scale.
void readValue(DataReader& in, TQ3Vector3D& v)
{
    v = in.vector3D();
}

void writeValue(Encoder& out, const TQ3Vector3D& v)
{
    out.vector3D(v);
}

void readValue(DataReader& in, TQ3RotateTransformData& data)
{
    data.axis = static_cast<TQ3Axis>(in.choice(kAxis));
    data.radians = in.f32();
}

void writeValue(Encoder& out, const TQ3RotateTransformData& data)
{
    out.choice(kAxis, static_cast<std::uint32_t>(data.axis));
    out.f32(data.radians);
}

void readValue(DataReader& in, TQ3Quaternion& q)
{
    q.w = in.f32();
    q.x = in.f32();
    q.y = in.f32();
    q.z = in.f32();
}

void writeValue(Encoder& out, const TQ3Quaternion& q)
{
    for (float v : {q.w, q.x, q.y, q.z})
        out.f32(v);
}

void readValue(DataReader& in, TQ3RotateAboutPointTransformData& data)
{
    data.axis = static_cast<TQ3Axis>(in.choice(kAxis));
    data.radians = in.f32();
    data.about = in.point3D();
}

void writeValue(Encoder& out, const TQ3RotateAboutPointTransformData& data)
{
    out.choice(kAxis, static_cast<std::uint32_t>(data.axis));
    out.f32(data.radians);
    out.point3D(data.about);
}

void readValue(DataReader& in, TQ3RotateAboutAxisTransformData& data)
{
    data.origin = in.point3D();
    data.orientation = in.vector3D();
    data.radians = in.f32();
}

void writeValue(Encoder& out, const TQ3RotateAboutAxisTransformData& data)
{
    out.point3D(data.origin);
    out.vector3D(data.orientation);
    out.f32(data.radians);
}

// A transform whose state is one value (view/Transform.h's ValueTransform),
// read through the class's checks.
template <class T>
Ref<SharedObject> readTransform(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    typename T::ValueType value{};
    readValue(in, value);
    return build<T>(findClass(T::kClassType)->name, value);
}

template <class T>
void writeTransform(WriteContext& context, const Object& object)
{
    Encoder& out = context.out();
    out.begin(T::kClassType, classOfType(T::kClassType)->name);
    writeValue(out, static_cast<const T&>(object).value());
    out.end();
}

Ref<SharedObject> readReset(ReadContext&, const Parts&)
{
    return Ref<SharedObject>(makeShared<ResetTransform>());
}

Ref<SharedObject> refuseLightData(ReadContext&, const Parts&)
{
    fail(kQ3ErrorInvalidMetafileObject, "LightData outside a light");
}

} // namespace

void addStateClasses(std::vector<ClassIO>& table)
{
    table.insert(
        table.end(),
        {
            {kQ3StyleTypeSubdivision, "SubdivisionStyle", readSubdivision, writeSubdivision},
            {kQ3StyleTypeAntiAlias, "AntiAliasStyle", readAntiAlias, writeAntiAlias},
            {kQ3StyleTypeFog, "FogStyle", readFog, writeFog},
            {kQ3StyleTypeHighlight, "HighlightStyle", readHighlight, writeHighlight},
            Q3_VALUE_STYLE(BackfacingStyle, &kBackfacing, false, kQ3StyleTypeBackfacing, "BackfacingStyle"),
            Q3_VALUE_STYLE(InterpolationStyle, &kInterpolation, false, kQ3StyleTypeInterpolation,
                           "InterpolationStyle"),
            Q3_VALUE_STYLE(FillStyle, &kFill, false, kQ3StyleTypeFill, "FillStyle"),
            Q3_VALUE_STYLE(OrientationStyle, &kOrientation, false, kQ3StyleTypeOrientation, "OrientationStyle"),
            Q3_VALUE_STYLE(PickIDStyle, static_cast<const Names*>(nullptr), false, kQ3StyleTypePickID, "PickIDStyle"),
            Q3_VALUE_STYLE(PickPartsStyle, &kPickParts, true, kQ3StyleTypePickParts, "PickPartsStyle"),
            Q3_VALUE_STYLE(CastShadowsStyle, &kBoolean, false, kQ3StyleTypeCastShadows, "CastShadowsStyle"),
            Q3_VALUE_STYLE(ReceiveShadowsStyle, &kBoolean, false, kQ3StyleTypeReceiveShadows,
                           "ReceiveShadowsStyle"),
            {kQ3IlluminationTypePhong, "PhongIllumination", readShader<PhongIllumination>,
             [](WriteContext& c, const Object&) { writeEmpty<kQ3IlluminationTypePhong>(c, "PhongIllumination"); }},
            {kQ3IlluminationTypeLambert, "LambertIllumination", readShader<LambertIllumination>,
             [](WriteContext& c, const Object&) {
                 writeEmpty<kQ3IlluminationTypeLambert>(c, "LambertIllumination");
             }},
            {kQ3IlluminationTypeNULL, "NULLIllumination", readShader<NULLIllumination>,
             [](WriteContext& c, const Object&) { writeEmpty<kQ3IlluminationTypeNULL>(c, "NULLIllumination"); }},
            {kQ3LightTypeAmbient, "AmbientLight", readAmbient, writeAmbient},
            {kQ3LightTypeDirectional, "DirectionalLight", readDirectional, writeDirectional},
            {kQ3LightTypePoint, "PointLight", readPointLight, writePointLight},
            {kQ3LightTypeSpot, "SpotLight", readSpotLight, writeSpotLight},
            {kTypeLightData, "LightData", refuseLightData, [](WriteContext&, const Object&) {}},
            {kQ3TransformTypeMatrix, "Matrix", readTransform<MatrixTransform>, writeTransform<MatrixTransform>},
            {kQ3TransformTypeTranslate, "Translate", readTransform<TranslateTransform>,
             writeTransform<TranslateTransform>},
            {kQ3TransformTypeScale, "Scale", readTransform<ScaleTransform>, writeTransform<ScaleTransform>},
            {kQ3TransformTypeRotate, "Rotate", readTransform<RotateTransform>, writeTransform<RotateTransform>},
            {kQ3TransformTypeQuaternion, "Quaternion", readTransform<QuaternionTransform>,
             writeTransform<QuaternionTransform>},
            {kQ3TransformTypeRotateAboutPoint, "RotateAboutPoint", readTransform<RotateAboutPointTransform>,
             writeTransform<RotateAboutPointTransform>},
            {kQ3TransformTypeRotateAboutAxis, "RotateAboutAxis", readTransform<RotateAboutAxisTransform>,
             writeTransform<RotateAboutAxisTransform>},
            {kQ3TransformTypeReset, "Reset", readReset,
             [](WriteContext& c, const Object&) { writeEmpty<kQ3TransformTypeReset>(c, "Reset"); }},
        });
}

} // namespace q3::io
