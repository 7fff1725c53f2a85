// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// View hints (3D Metafile Reference, "View Hints", "Image Dimensions
// Objects", "Image Masks", "Image Clear Color Objects"):
//   Container (
//     ViewHints ( )                                      'vwhn', no data
//     camera, lights, attribute set                      as objects
//     ImageDimensions ( width height )                   'imdm', Uns32 x 2
//     ImageMask ( width height rowBytes image )          'immk', Uns32 x 3 and
//                                                        RawData[rowBytes * height]
//     ImageClearColor ( r g b )                          'imcc', ColorRGB
//   )
// The reference lists the children as "renderer, camera, lights (as many as
// desired), attribute set, image dimensions, image mask, image clear color
// (all optional)". Q3 reads:
// - one camera; lights one by one (or light groups, whose lights are taken)
//   into one new light group;
// - one attribute set;
// - renderers and any other object of a type Q3 has no class for are kept
//   as unknown objects, written back unchanged after the other children: the
//   reference gives no renderer a layout and Q3's renderers have no 3DMF
//   form, so a renderer named in a file cannot be matched to one (the hints'
//   renderer, from the API, is not written);
// - the three image objects, at most once each. Their presence is the state:
//   ImageDimensions sets the dimensions state, ImageMask the mask state,
//   ImageClearColor the clear method kQ3ClearMethodWithColor (alpha 1).
// ImageMask's Data Format and Data Size (12 + image) give no bit order,
// while the page's example puts BigEndian after rowBytes: Q3 reads that word
// when a text file has it, and otherwise takes the bits most significant
// first, as the Mac stored them; it writes no bit order and its bits most
// significant first (a little-endian mask is converted).
// Anything else among the children, or an image object outside a ViewHints
// container, is kQ3ErrorInvalidMetafileSubObject / ...Object.

#include "io/ClassIO.h"

#include "core/DataLayout.h"
#include "core/Limits.h"
#include "geometry/Marker.h"
#include "group/Group.h"
#include "light/Light.h"
#include "view/Camera.h"
#include "view/ViewHints.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace q3::io {
namespace {

constexpr TQ3ObjectType kTypeImageDimensions = Q3_OBJECT_TYPE('i', 'm', 'd', 'm');
constexpr TQ3ObjectType kTypeImageMask = Q3_OBJECT_TYPE('i', 'm', 'm', 'k');
constexpr TQ3ObjectType kTypeImageClearColor = Q3_OBJECT_TYPE('i', 'm', 'c', 'c');

std::string nameOf(const Node& node)
{
    return node.name.empty() ? typeName(node.type) : node.name;
}

void requireEnd(const DataReader& in, const Node& node)
{
    if (!in.atEnd())
        fail(kQ3ErrorInvalidMetafileObject, "a " + nameOf(node) + " has more data than its fields");
}

void readDimensions(ReadContext& context, const Node& node, ViewHints& hints)
{
    DataReader in = context.reader(node);
    const std::uint32_t width = in.u32();
    const std::uint32_t height = in.u32();
    requireEnd(in, node);
    if (width == 0 || height == 0)
        fail(kQ3ErrorInvalidMetafileObject, "an ImageDimensions of " + std::to_string(width) + " x " +
                                                std::to_string(height) + " pixels");
    hints.setDimensions(width, height);
    hints.setDimensionsState(kQ3True);
}

unsigned char reversedBits(unsigned char byte)
{
    unsigned char out = 0;
    for (int bit = 0; bit < 8; ++bit)
        if (byte & (1u << bit))
            out |= static_cast<unsigned char>(0x80u >> bit);
    return out;
}

void readMask(ReadContext& context, const Node& node, ViewHints& hints)
{
    DataReader in = context.reader(node);
    TQ3Bitmap mask{};
    mask.width = in.u32();
    mask.height = in.u32();
    mask.rowBytes = in.u32();
    mask.bitOrder = kQ3EndianBig;
    const bool text = context.file().encoding == Encoding::kText;
    if (text && !in.atEnd()) {
        const std::string word = in.word();
        if (word == "BigEndian" || word == "LittleEndian")
            mask.bitOrder = word == "BigEndian" ? kQ3EndianBig : kQ3EndianLittle;
        else
            in.seek(in.tell() - 1);
    }
    const std::uint64_t size = std::uint64_t{mask.height} * mask.rowBytes;
    if (size == 0 || size > limits::kMaxArrayCount)
        fail(kQ3ErrorInvalidMetafileObject, "an ImageMask claims " + std::to_string(size) + " bytes of image");
    const std::string bytes = in.rawData(static_cast<std::size_t>(size));
    requireEnd(in, node);
    std::vector<unsigned char> image(bytes.begin(), bytes.end());
    mask.image = image.data();
    try {
        Marker::checkBitmap(mask);
    } catch (const Error& error) {
        fail(kQ3ErrorInvalidMetafileObject, std::string("the file's ImageMask breaks a rule: ") + error.what());
    }
    hints.setMask(mask);
    hints.setMaskState(kQ3True);
}

void readClearColor(ReadContext& context, const Node& node, ViewHints& hints)
{
    DataReader in = context.reader(node);
    const TQ3ColorRGB color = in.color();
    requireEnd(in, node);
    if (!std::isfinite(color.r) || !std::isfinite(color.g) || !std::isfinite(color.b))
        fail(kQ3ErrorInvalidMetafilePrimitive, "an ImageClearColor has a non-finite component");
    hints.setClearColor(TQ3ColorARGB{1.0f, color.r, color.g, color.b});
    hints.setClearMethod(kQ3ClearMethodWithColor);
}

// Adds a light, or a light group's lights, to the hints' light group.
void addLights(ViewHints& hints, const SharedObject& object)
{
    if (!hints.lightGroup())
        hints.setLightGroup(makeShared<LightGroup>());
    Group& lights = *hints.lightGroup();
    if (object.isType(kQ3ShapeTypeLight)) {
        lights.add(Ref<SharedObject>::retain(const_cast<SharedObject*>(&object)));
        return;
    }
    for (const Group::Node& item : static_cast<const Group&>(object).nodes())
        lights.add(item.object);
}

Ref<SharedObject> readViewHints(ReadContext& context, const Parts& parts)
{
    requireEnd(context.reader(parts.root), parts.root);
    Ref<ViewHints> hints = makeShared<ViewHints>();
    if (parts.children == nullptr)
        return Ref<SharedObject>(hints);
    bool camera = false, attributes = false, dimensions = false, mask = false, color = false;
    const auto once = [](bool& seen, const char* what) {
        if (seen)
            fail(kQ3ErrorInvalidMetafileSubObject, std::string("a ViewHints with a second ") + what);
        seen = true;
    };
    const std::vector<Node>& children = *parts.children;
    for (std::size_t index = 1; index < children.size();) {
        const Node& node = children[index];
        if (node.type == kTypeImageDimensions) {
            once(dimensions, "ImageDimensions");
            readDimensions(context, node, *hints);
            ++index;
            continue;
        }
        if (node.type == kTypeImageMask) {
            once(mask, "ImageMask");
            readMask(context, node, *hints);
            ++index;
            continue;
        }
        if (node.type == kTypeImageClearColor) {
            once(color, "ImageClearColor");
            readClearColor(context, node, *hints);
            ++index;
            continue;
        }
        Ref<SharedObject> object = context.sequenceItem(children, index);
        if (object->isType(kQ3ShapeTypeCamera)) {
            once(camera, "camera");
            hints->setCamera(Ref<Camera>::retain(static_cast<Camera*>(object.get())));
        } else if (object->isType(kQ3SetTypeAttribute)) {
            once(attributes, "attribute set");
            hints->setAttributeSet(Ref<AttributeSet>::retain(static_cast<AttributeSet*>(object.get())));
        } else if (object->isType(kQ3ShapeTypeLight) || object->isType(kQ3GroupTypeLight)) {
            addLights(*hints, *object);
        } else if (object->isType(kQ3ShapeTypeUnknown)) {
            hints->addUnknownChild(std::move(object));
        } else {
            fail(kQ3ErrorInvalidMetafileSubObject,
                 std::string("a ViewHints holds a ") + object->classInfo().name +
                     "; its children are a renderer, a camera, lights, an attribute set and image objects");
        }
    }
    return Ref<SharedObject>(hints);
}

void writeMask(Encoder& out, const TQ3Bitmap& mask)
{
    const std::size_t size = std::size_t(mask.rowBytes) * mask.height;
    std::vector<unsigned char> image(mask.image, mask.image + size);
    if (mask.bitOrder == kQ3EndianLittle)
        for (unsigned char& byte : image)
            byte = reversedBits(byte);
    out.begin(kTypeImageMask, "ImageMask");
    out.u32(static_cast<std::uint32_t>(mask.width));
    out.u32(static_cast<std::uint32_t>(mask.height));
    out.u32(static_cast<std::uint32_t>(mask.rowBytes));
    out.rawData(image.data(), size);
    out.end();
}

void writeViewHints(WriteContext& context, const Object& object)
{
    const ViewHints& hints = static_cast<const ViewHints&>(object);
    std::vector<const Light*> lights;
    if (const Group* group = hints.lightGroup().get())
        for (const Group::Node& item : group->nodes())
            lights.push_back(static_cast<const Light*>(item.object.get()));
    const bool dimensions = hints.dimensionsState() == kQ3True && hints.width() != 0;
    const bool mask = hints.maskState() == kQ3True && hints.mask().image != nullptr;
    const bool color = hints.clearMethod() == kQ3ClearMethodWithColor;
    const bool children = hints.camera() || !lights.empty() ||
                          WriteContext::hasAttributes(hints.attributeSet().get()) || dimensions || mask || color ||
                          !hints.unknownChildren().empty();
    maybeContainer(context, children, [&] {
        Encoder& out = context.out();
        out.begin(kQ3SharedTypeViewHints, "ViewHints");
        out.end();
        if (hints.camera())
            context.object(*hints.camera());
        for (const Light* light : lights)
            context.object(*light);
        context.attributeSet(hints.attributeSet().get());
        if (dimensions) {
            out.begin(kTypeImageDimensions, "ImageDimensions");
            out.u32(static_cast<std::uint32_t>(hints.width()));
            out.u32(static_cast<std::uint32_t>(hints.height()));
            out.end();
        }
        if (mask)
            writeMask(out, hints.mask());
        if (color) {
            const TQ3ColorARGB& c = hints.clearColor();
            out.begin(kTypeImageClearColor, "ImageClearColor");
            out.color(TQ3ColorRGB{c.r, c.g, c.b});
            out.end();
        }
        for (const Ref<SharedObject>& child : hints.unknownChildren())
            context.object(*child);
    });
}

Ref<SharedObject> refuseImagePart(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject, nameOf(parts.root) + " outside a ViewHints");
}

void writeNothing(WriteContext&, const Object&) {}

} // namespace

void addViewHintsClasses(std::vector<ClassIO>& table)
{
    table.insert(table.end(), {
                                  {kQ3SharedTypeViewHints, "ViewHints", readViewHints, writeViewHints},
                                  {kTypeImageDimensions, "ImageDimensions", refuseImagePart, writeNothing},
                                  {kTypeImageMask, "ImageMask", refuseImagePart, writeNothing},
                                  {kTypeImageClearColor, "ImageClearColor", refuseImagePart, writeNothing},
                              });
}

} // namespace q3::io
