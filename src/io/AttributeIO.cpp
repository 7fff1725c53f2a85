// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Attribute sets: `Container ( AttributeSet ( ) DiffuseColor ( r g b ) ... )`,
// one element object per attribute (3D Metafile Reference, "Attribute
// objects"). The element objects exist only inside a set's container.

#include "io/ClassIO.h"

#include "core/AttributeSet.h"
#include "core/ErrorManager.h"
#include "io/CustomElements.h"

#include <cstring>

namespace q3::io {
namespace {

enum class Kind { kColor, kFloat, kVector, kParam, kTangent, kSwitch };

struct Element {
    TQ3AttributeType attribute;
    TQ3ObjectType type;
    const char* name;
    Kind kind;
};

const Element kElements[] = {
    {kQ3AttributeTypeSurfaceUV, Q3_OBJECT_TYPE('s', 'r', 'u', 'v'), "SurfaceUV", Kind::kParam},
    {kQ3AttributeTypeShadingUV, Q3_OBJECT_TYPE('s', 'h', 'u', 'v'), "ShadingUV", Kind::kParam},
    {kQ3AttributeTypeNormal, Q3_OBJECT_TYPE('n', 'r', 'm', 'l'), "Normal", Kind::kVector},
    {kQ3AttributeTypeAmbientCoefficient, Q3_OBJECT_TYPE('c', 'a', 'm', 'b'), "AmbientCoefficient", Kind::kFloat},
    {kQ3AttributeTypeDiffuseColor, Q3_OBJECT_TYPE('k', 'd', 'i', 'f'), "DiffuseColor", Kind::kColor},
    {kQ3AttributeTypeSpecularColor, Q3_OBJECT_TYPE('k', 's', 'p', 'c'), "SpecularColor", Kind::kColor},
    {kQ3AttributeTypeSpecularControl, Q3_OBJECT_TYPE('c', 's', 'p', 'c'), "SpecularControl", Kind::kFloat},
    {kQ3AttributeTypeTransparencyColor, Q3_OBJECT_TYPE('k', 'x', 'p', 'r'), "TransparencyColor", Kind::kColor},
    {kQ3AttributeTypeSurfaceTangent, Q3_OBJECT_TYPE('s', 'r', 't', 'n'), "SurfaceTangent", Kind::kTangent},
    {kQ3AttributeTypeHighlightState, Q3_OBJECT_TYPE('h', 'l', 's', 't'), "HighlightState", Kind::kSwitch},
};

const std::vector<std::pair<const char*, std::uint32_t>> kSwitch = {{"Off", kQ3Off}, {"On", kQ3On}};

const Element* elementOfType(TQ3ObjectType type)
{
    for (const Element& element : kElements)
        if (element.type == type)
            return &element;
    return nullptr;
}

// A subobject of an attribute set that is no plain-data element: the
// surface shader (a texture shader in its container, or a reference to one:
// kQ3AttributeTypeSurfaceShader, as Apple-era models keep their textures),
// or an element Q3 has no class for, kept as the unknown object it reads as
// and written back. Any other object is no attribute: a warning says it is
// left out.
void readOtherElement(ReadContext& context, AttributeSet& set, const Node& node)
{
    Ref<SharedObject> object = context.object(node);
    if (object->isType(kQ3ShaderTypeSurface)) {
        if (set.shader() != nullptr)
            errors::postWarning(kQ3WarningInvalidSubObjectForObject,
                                "an attribute set holds two surface shaders; the last one is kept");
        set.addShader(std::move(object));
    } else if (object->isType(kQ3ShapeTypeUnknown)) {
        errors::postWarning(kQ3WarningUnknownElementType,
                            "an attribute set holds " +
                                (node.name.empty() ? typeName(node.type) : node.name) +
                                ", an element Q3 does not know; it is kept as an unknown object and written back");
        set.addOtherElement(std::move(object));
    } else {
        errors::postWarning(kQ3WarningInvalidSubObjectForObject,
                            std::string("an attribute set holds a ") + object->classInfo().name +
                                ", which is no attribute; it is left out");
    }
}

Ref<SharedObject> readAttributeSet(ReadContext& context, const Parts& parts)
{
    Ref<AttributeSet> set = makeShared<AttributeSet>();
    for (const Node* node : parts.subobjects) {
        const Element* element = elementOfType(node->type);
        if (element == nullptr) {
            readOtherElement(context, *set, *node);
            continue;
        }
        DataReader in = context.reader(*node);
        unsigned char value[24];
        switch (element->kind) {
        case Kind::kColor: {
            const TQ3ColorRGB c = in.color();
            std::memcpy(value, &c, sizeof c);
            break;
        }
        case Kind::kFloat: {
            const float f = in.f32();
            std::memcpy(value, &f, sizeof f);
            break;
        }
        case Kind::kVector: {
            const TQ3Vector3D v = in.vector3D();
            std::memcpy(value, &v, sizeof v);
            break;
        }
        case Kind::kParam: {
            const TQ3Param2D p = in.param2D();
            std::memcpy(value, &p, sizeof p);
            break;
        }
        case Kind::kTangent: {
            TQ3Tangent2D t;
            t.uTangent = in.vector3D();
            t.vTangent = in.vector3D();
            std::memcpy(value, &t, sizeof t);
            break;
        }
        case Kind::kSwitch: {
            const TQ3Switch s = static_cast<TQ3Switch>(in.choice(kSwitch));
            std::memcpy(value, &s, sizeof s);
            break;
        }
        }
        try {
            set->add(element->attribute, value);
        } catch (const Error& error) {
            fail(kQ3ErrorInvalidMetafileObject, std::string("the file's ") + element->name + ": " + error.what());
        }
    }
    return Ref<SharedObject>(std::move(set));
}

void writeAttributeSet(WriteContext& context, const Object& object)
{
    const auto& set = static_cast<const AttributeSet&>(object);
    Encoder& out = context.out();
    out.begin(kTypeContainer, "Container");
    out.begin(kQ3SetTypeAttribute, "AttributeSet");
    out.end();
    for (const Element& element : kElements) {
        if (!set.contains(element.attribute))
            continue;
        unsigned char value[24];
        set.get(element.attribute, value);
        out.begin(element.type, element.name);
        switch (element.kind) {
        case Kind::kColor: {
            TQ3ColorRGB c;
            std::memcpy(&c, value, sizeof c);
            out.color(c);
            break;
        }
        case Kind::kFloat: {
            float f;
            std::memcpy(&f, value, sizeof f);
            out.f32(f);
            break;
        }
        case Kind::kVector: {
            TQ3Vector3D v;
            std::memcpy(&v, value, sizeof v);
            out.vector3D(v);
            break;
        }
        case Kind::kParam: {
            TQ3Param2D p;
            std::memcpy(&p, value, sizeof p);
            out.param2D(p);
            break;
        }
        case Kind::kTangent: {
            TQ3Tangent2D t;
            std::memcpy(&t, value, sizeof t);
            out.vector3D(t.uTangent);
            out.vector3D(t.vTangent);
            break;
        }
        case Kind::kSwitch: {
            TQ3Switch s;
            std::memcpy(&s, value, sizeof s);
            out.choice(kSwitch, static_cast<std::uint32_t>(s));
            break;
        }
        }
        out.end();
    }
    if (const SharedObject* shader = set.shader())
        context.object(*shader);
    for (const Ref<SharedObject>& other : set.otherElements())
        context.object(*other);
    writeCustomElements(context, set);
    out.end();
}

Ref<SharedObject> refuseElement(ReadContext&, const Parts& parts)
{
    fail(kQ3ErrorInvalidMetafileObject, (parts.root.name.empty() ? typeName(parts.root.type) : parts.root.name) +
                                            " outside an attribute set or a geometry");
}

void writeNothing(WriteContext&, const Object&) {}

} // namespace

void addAttributeClasses(std::vector<ClassIO>& table)
{
    table.push_back({kQ3SetTypeAttribute, "AttributeSet", readAttributeSet, writeAttributeSet});
    for (const Element& element : kElements)
        table.push_back({element.type, element.name, refuseElement, writeNothing});
    // The subobjects geometries hold: known by name, read only by their
    // geometry.
    table.push_back({Q3_OBJECT_TYPE('v', 'a', 's', 'l'), "VertexAttributeSetList", refuseElement, writeNothing});
    table.push_back({Q3_OBJECT_TYPE('c', 'a', 'p', 's'), "Caps", refuseElement, writeNothing});
    table.push_back({Q3_OBJECT_TYPE('a', 't', 'a', 'r'), "AttributeArray", refuseElement, writeNothing});
}

} // namespace q3::io
