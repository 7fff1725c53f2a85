// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "core/AttributeSet.h"

#include "core/EnumValue.h"
#include "core/ShapeVisitor.h"

#include <cmath>
#include <cstring>

namespace q3 {

const ClassInfo kSetClass{kQ3SharedTypeSet, &kSharedClass, "set"};
const ClassInfo kAttributeSetClass{kQ3SetTypeAttribute, &kSetClass, "attribute set"};

namespace {

std::size_t floatCount(TQ3AttributeType type)
{
    switch (type) {
    case kQ3AttributeTypeSurfaceUV:
    case kQ3AttributeTypeShadingUV:
        return 2;
    case kQ3AttributeTypeNormal:
    case kQ3AttributeTypeDiffuseColor:
    case kQ3AttributeTypeSpecularColor:
    case kQ3AttributeTypeTransparencyColor:
        return 3;
    case kQ3AttributeTypeAmbientCoefficient:
    case kQ3AttributeTypeSpecularControl:
        return 1;
    case kQ3AttributeTypeSurfaceTangent:
        return 6;
    default:
        return 0;
    }
}

} // namespace

std::size_t Set::slotIndex(TQ3AttributeType type)
{
    if (type < kFirstType || type > kLastStoredType)
        fail(kQ3ErrorAttributeInvalidType,
             "attribute type " + std::to_string(type) +
                 " is not one Q3 stores (1 to 11: surface UV ... highlight state, surface shader)");
    return static_cast<std::size_t>(type - kFirstType);
}

std::size_t Set::dataSize(TQ3AttributeType type)
{
    slotIndex(type);
    // A surface shader value is a handle; whoever stores an array of them
    // (a TriMesh's attribute arrays) holds a reference per element.
    if (type == kQ3AttributeTypeSurfaceShader)
        return sizeof(TQ3Object);
    if (type == kQ3AttributeTypeHighlightState)
        return sizeof(TQ3Switch);
    return floatCount(type) * sizeof(float);
}

bool AttributeValues::copy(TQ3AttributeType type, void* data, std::size_t size) const
{
    const auto& slot = m_slots[type - kFirstType];
    if (!slot)
        return false;
    std::memcpy(data, slot->data(), size);
    return true;
}

void AttributeValues::overlay(const AttributeValues& other)
{
    for (std::size_t i = 0; i < m_slots.size(); ++i)
        if (other.m_slots[i])
            m_slots[i] = other.m_slots[i];
    if (other.m_surfaceShader)
        m_surfaceShader = other.m_surfaceShader;
}

std::shared_ptr<CustomClass> Set::customClass(TQ3ElementType type)
{
    if (type >= kQ3ElementTypeNone && type <= kQ3ElementTypeSet)
        return nullptr;
    std::shared_ptr<CustomClass> found = findCustomClass(type);
    if (found && found->kind() == CustomClass::Kind::kObject)
        return nullptr;
    return found;
}

std::shared_ptr<CustomClass> Set::checkedType(TQ3AttributeType type)
{
    if (std::shared_ptr<CustomClass> custom = customClass(type))
        return custom;
    slotIndex(type);
    return nullptr;
}

Object* Set::duplicate() const
{
    Ref<Set> copy = makeShared<Set>();
    copyContentsTo(*copy);
    return copy.detach();
}

Object* AttributeSet::duplicate() const
{
    Ref<AttributeSet> copy = makeShared<AttributeSet>();
    copyContentsTo(*copy);
    return copy.detach();
}

void Set::copyContentsTo(Set& copy) const
{
    // The copy shares the surface shader and the unknown elements (shared
    // objects, as a set read from a file shares them), like Q3Object_Duplicate
    // of a geometry shares nothing but makes new attribute sets.
    // Custom elements are copied by their class's copy-duplicate method.
    copy.m_values = m_values;
    copy.m_others = m_others;
    for (const auto& [type, element] : m_custom)
        copy.m_custom.emplace(type, std::make_unique<CustomElement>(*element));
}

Ref<AttributeSet> AttributeSet::fromValues(const AttributeValues& values)
{
    Ref<AttributeSet> set = makeShared<AttributeSet>();
    set->m_values = values;
    return set;
}

void AttributeSet::accept(ShapeVisitor& visitor) const
{
    visitor.visitAttributeSet(*this);
}

std::string Set::valueProblem(TQ3AttributeType type, const void* data)
{
    if (type == kQ3AttributeTypeHighlightState) {
        TQ3Switch value;
        std::memcpy(&value, data, sizeof value);
        if (enumValue(value) != kQ3On && enumValue(value) != kQ3Off)
            return "a highlight state must be kQ3On or kQ3Off";
        return {};
    }
    float values[6];
    std::memcpy(values, data, floatCount(type) * sizeof(float));
    for (std::size_t i = 0; i < floatCount(type); ++i)
        if (!std::isfinite(values[i]))
            return "attribute " + std::to_string(type) + " component " + std::to_string(i) +
                   " is not a finite number";
    return {};
}

void Set::add(TQ3AttributeType type, const void* data)
{
    if (std::shared_ptr<CustomClass> custom = checkedType(type)) {
        requireNonNull(data, "data");
        const auto found = m_custom.find(type);
        if (found != m_custom.end())
            found->second->replace(data);
        else
            m_custom.emplace(type, std::make_unique<CustomElement>(std::move(custom), data));
        markEdited();
        return;
    }
    const std::size_t index = slotIndex(type);
    if (type == kQ3AttributeTypeSurfaceShader)
        fail(kQ3ErrorInternalError, "a surface shader is stored with addShader");
    requireNonNull(data, "data");
    AttributeValues::Slot slot{};
    std::memcpy(slot.data(), data, dataSize(type));
    const std::string problem = valueProblem(type, slot.data());
    if (!problem.empty())
        fail(kQ3ErrorInvalidParameter, problem);
    m_values.m_slots[index] = slot;
    markEdited();
}

void Set::get(TQ3AttributeType type, void* data) const
{
    if (checkedType(type)) {
        requireNonNull(data, "data");
        const auto found = m_custom.find(type);
        if (found == m_custom.end())
            fail(kQ3ErrorAttributeNotContained, "the set holds no element of type " + std::to_string(type));
        found->second->get(data);
        return;
    }
    if (type == kQ3AttributeTypeSurfaceShader)
        fail(kQ3ErrorInternalError, "a surface shader is read with shader()");
    requireNonNull(data, "data");
    if (!m_values.copy(type, data, dataSize(type)))
        fail(kQ3ErrorAttributeNotContained,
             "the set holds no attribute of type " + std::to_string(type));
}

bool Set::contains(TQ3AttributeType type) const
{
    if (checkedType(type))
        return m_custom.count(type) != 0;
    return m_values.contains(type);
}

void Set::addShader(Ref<SharedObject> shader)
{
    requireNonNull(shader.get(), "shader");
    m_values.m_surfaceShader = std::move(shader);
    markEdited();
}

void Set::requireElementType(TQ3ElementType type)
{
    if ((type < kFirstType || type > kLastStoredType) && !customClass(type))
        fail(kQ3ErrorUnknownElementType,
             "element type " + std::to_string(type) +
                 " has no element class in Q3 (the attribute types 1 to 11 and the registered custom element "
                 "and attribute classes have)");
}

void Set::requireWalkType(TQ3AttributeType type)
{
    if (type != kQ3AttributeTypeNone)
        checkedType(type);
}

TQ3AttributeType Set::nextType(TQ3AttributeType type) const
{
    if (type != kQ3AttributeTypeNone && checkedType(type)) {
        const auto after = m_custom.upper_bound(type);
        return after == m_custom.end() ? TQ3AttributeType{kQ3AttributeTypeNone} : after->first;
    }
    requireWalkType(type);
    for (TQ3AttributeType next = type + 1; next <= kLastStoredType; ++next)
        if (m_values.contains(next))
            return next;
    return m_custom.empty() ? TQ3AttributeType{kQ3AttributeTypeNone} : m_custom.begin()->first;
}

void Set::addCustomElement(std::unique_ptr<CustomElement> element)
{
    const TQ3ElementType type = element->elementClass().type();
    m_custom[type] = std::move(element);
    markEdited();
}

std::vector<std::unique_ptr<CustomElement>> Set::takeCustomElements()
{
    std::vector<std::unique_ptr<CustomElement>> taken;
    for (auto& [type, element] : m_custom)
        taken.push_back(std::move(element));
    m_custom.clear();
    if (!taken.empty())
        markEdited();
    return taken;
}

void Set::addOtherElement(Ref<SharedObject> element)
{
    m_others.push_back(std::move(element));
    markEdited();
}

void Set::clear(TQ3AttributeType type)
{
    if (checkedType(type)) {
        const auto found = m_custom.find(type);
        if (found == m_custom.end())
            fail(kQ3ErrorAttributeNotContained, "the set holds no element of type " + std::to_string(type));
        m_custom.erase(found);
        markEdited();
        return;
    }
    const std::size_t index = slotIndex(type);
    if (type == kQ3AttributeTypeSurfaceShader) {
        if (!m_values.m_surfaceShader)
            fail(kQ3ErrorAttributeNotContained, "the set holds no surface shader");
        m_values.m_surfaceShader.reset();
        markEdited();
        return;
    }
    if (!m_values.m_slots[index])
        fail(kQ3ErrorAttributeNotContained,
             "the set holds no attribute of type " + std::to_string(type));
    m_values.m_slots[index].reset();
    markEdited();
}

void Set::empty()
{
    m_values = AttributeValues();
    m_others.clear();
    m_custom.clear();
    markEdited();
}

Set& ObjectElements::ownSet()
{
    if (!own)
        own = makeShared<Set>();
    return *own;
}

void AttributeSet::inheritFrom(const AttributeSet& other)
{
    m_values.overlay(other.m_values);
    markEdited();
}

void AttributeSet::inherit(const AttributeSet& parent, const AttributeSet& child)
{
    // Built apart first: parent or child may be this set.
    AttributeValues result = parent.m_values;
    result.overlay(child.m_values);
    // Custom attributes: the child's, and the parent's the child lacks whose
    // class lets them be inherited (kQ3XMethodTypeAttributeInherit), each
    // copied by copy-inherit; custom elements that are no attributes stay
    // behind.
    std::map<TQ3ElementType, std::unique_ptr<CustomElement>> custom;
    for (const auto& [type, element] : child.m_custom)
        if (element->elementClass().kind() == CustomClass::Kind::kAttribute)
            custom.emplace(type, element->inheritCopy());
    for (const auto& [type, element] : parent.m_custom)
        if (element->elementClass().kind() == CustomClass::Kind::kAttribute && element->inherits() &&
            custom.count(type) == 0)
            custom.emplace(type, element->inheritCopy());
    m_values = std::move(result);
    m_custom = std::move(custom);
    m_others.clear();
    markEdited();
}

} // namespace q3
