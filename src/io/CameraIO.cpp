// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Cameras (3D Metafile Reference, "Camera objects"; Apple's metafile parser,
// MF3D's mfobjcts.h and mfsubobj.h). A camera is its kind's own data
//   OrthographicCamera     'orth'  left top right bottom
//   ViewPlaneCamera        'vwpl'  viewPlane halfWidthAtViewPlane
//                                  halfHeightAtViewPlane centerXOnViewPlane
//                                  centerYOnViewPlane
//   ViewAngleAspectCamera  'vana'  fieldOfView aspectRatioXToY
// followed, in its container, by the common data as three subobjects:
//   CameraPlacement  'cmpl'  location pointOfInterest upVector
//   CameraRange      'cmrg'  hither yon
//   CameraViewPort   'cmvp'  origin.x origin.y width height
// A missing subobject takes the reference's default: placement at (0 0 1)
// looking at the origin with +y up, view port (-1 1) 2 x 2. The reference's
// default range, hither "epsilon" and yon "infinity", has no finite form, and
// Q3's cameras need finite values: Q3 reads a missing range as
// kDefaultRange. Q3 always writes all three. Every camera read goes through
// its class's checks, so a file cannot make a camera the API would refuse.

#include "io/ClassIO.h"

#include "view/Camera.h"

#include <string>

namespace q3::io {
namespace {

constexpr TQ3ObjectType kTypePlacement = Q3_OBJECT_TYPE('c', 'm', 'p', 'l');
constexpr TQ3ObjectType kTypeRange = Q3_OBJECT_TYPE('c', 'm', 'r', 'g');
constexpr TQ3ObjectType kTypeViewPort = Q3_OBJECT_TYPE('c', 'm', 'v', 'p');

constexpr TQ3CameraPlacement kDefaultPlacement{{0, 0, 1}, {0, 0, 0}, {0, 1, 0}};
constexpr TQ3CameraRange kDefaultRange{0.001f, 1000000.0f};
constexpr TQ3CameraViewPort kDefaultViewPort{{-1, 1}, 2, 2};

std::string nameOf(const Node& node)
{
    return node.name.empty() ? typeName(node.type) : node.name;
}

void requireEnd(const DataReader& in, const Node& node)
{
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a " + nameOf(node) + " has more data than its fields");
}

// The node of a camera subobject of that type, looking through a reference
// (Parts::find returns the reference itself), or null.
const Node* subobject(ReadContext& context, const Parts& parts, TQ3ObjectType type)
{
    const Node* node = parts.find(type);
    if (node == nullptr)
        return nullptr;
    if (node->type == kTypeReference) {
        DataReader in = context.reader(*node);
        const std::uint32_t id = in.u32();
        const auto found = context.file().references.find(id);
        if (found == context.file().references.end())
            fail(kQ3ErrorInvalidMetafileObject,
                 "reference " + std::to_string(id) + " is in no table of contents: it refers to nothing");
        node = found->second;
    }
    if (node->type != type)
        fail(kQ3ErrorInvalidMetafileSubObject, "a camera's " + typeName(type) + " is a " + nameOf(*node));
    return node;
}

TQ3CameraData readCommon(ReadContext& context, const Parts& parts)
{
    TQ3CameraData data{kDefaultPlacement, kDefaultRange, kDefaultViewPort};
    if (const Node* node = subobject(context, parts, kTypePlacement)) {
        DataReader in = context.reader(*node);
        data.placement.cameraLocation = in.point3D();
        data.placement.pointOfInterest = in.point3D();
        data.placement.upVector = in.vector3D();
        requireEnd(in, *node);
    }
    if (const Node* node = subobject(context, parts, kTypeRange)) {
        DataReader in = context.reader(*node);
        data.range.hither = in.f32();
        data.range.yon = in.f32();
        requireEnd(in, *node);
    }
    if (const Node* node = subobject(context, parts, kTypeViewPort)) {
        DataReader in = context.reader(*node);
        data.viewPort.origin.x = in.f32();
        data.viewPort.origin.y = in.f32();
        data.viewPort.width = in.f32();
        data.viewPort.height = in.f32();
        requireEnd(in, *node);
    }
    return data;
}

void writeCommon(Encoder& out, const TQ3CameraData& data)
{
    out.begin(kTypePlacement, "CameraPlacement");
    out.point3D(data.placement.cameraLocation);
    out.point3D(data.placement.pointOfInterest);
    out.vector3D(data.placement.upVector);
    out.end();
    out.begin(kTypeRange, "CameraRange");
    out.f32(data.range.hither);
    out.f32(data.range.yon);
    out.end();
    out.begin(kTypeViewPort, "CameraViewPort");
    out.f32(data.viewPort.origin.x);
    out.f32(data.viewPort.origin.y);
    out.f32(data.viewPort.width);
    out.f32(data.viewPort.height);
    out.end();
}

// Builds a camera from file data through its class's checks.
template <class T, class Data>
Ref<SharedObject> build(const char* what, const Data& data)
{
    try {
        T::validate(data);
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidMetafileObject, std::string("the file's ") + what + " breaks a rule: " + error.what());
    }
    return Ref<SharedObject>(makeShared<T>(data));
}

// A camera of kind C: its own fields (C::kFields, floats in order), then,
// in its container, the common data.
template <class C>
Ref<SharedObject> readCamera(ReadContext& context, const Parts& parts)
{
    DataReader in = context.reader(parts.root);
    typename C::DataType data{};
    for (const CameraField<typename C::DataType>& field : C::kFields)
        data.*field.member = in.f32();
    requireEnd(in, parts.root);
    data.cameraData = readCommon(context, parts);
    return build<C>(findClass(C::kClassType)->name, data);
}

template <class C>
void writeCamera(WriteContext& context, const Object& object)
{
    const typename C::DataType data = static_cast<const C&>(object).kindData();
    maybeContainer(context, true, [&] {
        Encoder& out = context.out();
        out.begin(C::kClassType, classOfType(C::kClassType)->name);
        for (const CameraField<typename C::DataType>& field : C::kFields)
            out.f32(data.*field.member);
        out.end();
        writeCommon(out, data.cameraData);
    });
}

Ref<SharedObject> refuseCameraPart(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject, nameOf(parts.root) + " outside a camera");
}

void writeNothing(WriteContext&, const Object&) {}

} // namespace

void addCameraClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(), {
                                  {kQ3CameraTypeOrthographic, "OrthographicCamera", readCamera<OrthographicCamera>,
                                   writeCamera<OrthographicCamera>},
                                  {kQ3CameraTypeViewPlane, "ViewPlaneCamera", readCamera<ViewPlaneCamera>,
                                   writeCamera<ViewPlaneCamera>},
                                  {kQ3CameraTypeViewAngleAspect, "ViewAngleAspectCamera",
                                   readCamera<ViewAngleAspectCamera>, writeCamera<ViewAngleAspectCamera>},
                                  {kTypePlacement, "CameraPlacement", refuseCameraPart, writeNothing},
                                  {kTypeRange, "CameraRange", refuseCameraPart, writeNothing},
                                  {kTypeViewPort, "CameraViewPort", refuseCameraPart, writeNothing},
                              });
}

} // namespace q3::io
