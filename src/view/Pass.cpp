// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/Pass.h"

#include "core/AttributeSet.h"
#include "core/EnumValue.h"
#include "core/Limits.h"
#include "geometry/Geometry.h"
#include "group/Group.h"
#include "shader/Shader.h"
#include "style/Style.h"
#include "view/Transform.h"

namespace q3 {

AttributeValues defaultAttributes(const AttributeSet* viewDefaults)
{
    // The values of QD3DView.h's kQ3ViewDefault* constants.
    Ref<AttributeSet> defaults = makeShared<AttributeSet>();
    const float ambient = 1.0f;
    const TQ3ColorRGB diffuse{1.0f, 1.0f, 1.0f};
    const TQ3ColorRGB specular{0.5f, 0.5f, 0.5f};
    const float control = 4.0f;
    const TQ3ColorRGB transparency{1.0f, 1.0f, 1.0f};
    const TQ3Switch highlight = kQ3Off;
    defaults->add(kQ3AttributeTypeAmbientCoefficient, &ambient);
    defaults->add(kQ3AttributeTypeDiffuseColor, &diffuse);
    defaults->add(kQ3AttributeTypeSpecularColor, &specular);
    defaults->add(kQ3AttributeTypeSpecularControl, &control);
    defaults->add(kQ3AttributeTypeTransparencyColor, &transparency);
    defaults->add(kQ3AttributeTypeHighlightState, &highlight);
    AttributeValues values = defaults->values();
    if (viewDefaults != nullptr)
        values.overlay(viewDefaults->values());
    return values;
}

namespace {

// A surface shader in attribute values submitted to the view becomes the
// view's surface shader, as the shader submitted itself would: the later of
// the two is in force. (AttributeValues holds only surface shaders.)
void applySurfaceShader(const AttributeValues& values, DrawState& draw)
{
    if (const SharedObject* shader = values.surfaceShader())
        static_cast<const Shader&>(*shader).apply(draw);
}

} // namespace

Pass::Pass(std::optional<Window> window, const AttributeValues& attributes) : m_window(std::move(window))
{
    m_state.attributes = attributes;
    applySurfaceShader(attributes, m_state.draw);
}

void Pass::visitAttributeSet(const AttributeSet& attributes)
{
    m_state.attributes.overlay(attributes.values());
    applySurfaceShader(attributes.values(), m_state.draw);
}

void Pass::visitStyle(const Style& style)
{
    style.apply(m_state.draw);
}

void Pass::visitShader(const Shader& shader)
{
    shader.apply(m_state.draw);
}

void Pass::visitTransform(const Transform& transform)
{
    if (transform.isReset())
        m_state.localToWorld = Matrix(1.0);
    else
        m_state.localToWorld = then(fromQ3(transform.matrix()), m_state.localToWorld);
}

void Pass::push()
{
    m_stack.push_back(m_state);
}

void Pass::pop()
{
    const std::size_t floor = m_groups.empty() ? 0 : m_groups.back().floor;
    if (m_stack.size() <= floor)
        fail(kQ3ErrorNothingToPop, m_groups.empty()
                                       ? "no state pushed in this traversal is left to pop"
                                       : "no state pushed inside this display group is left to pop");
    m_state = m_stack.back();
    m_stack.pop_back();
}

TessellationSetting Pass::tessellationSetting() const
{
    TessellationSetting setting;
    setting.style = m_state.draw.subdivision;
    setting.localToWorld = m_state.localToWorld;
    setting.window = m_window;
    setting.cullOutsideView = m_cullCurves && m_window.has_value();
    return setting;
}

SubdivisionMeasure Pass::subdivisionMeasure() const
{
    SubdivisionMeasure measure = measureFor(tessellationSetting());
    measure.curveScratch = m_curveScratch;
    return measure;
}

Ref<Geometry> Pass::decomposed(const Geometry& geometry) const
{
    if (geometry.isPrimitive())
        return nullptr;
    return geometry.decomposed(*this);
}

TQ3ColorRGB Pass::colorOf(const AttributeSet* own) const
{
    if (own != nullptr)
        if (const std::optional<TQ3ColorRGB> color = own->diffuseColor())
            return *color;
    return m_state.attributes.diffuseColor().value_or(TQ3ColorRGB{1.0f, 1.0f, 1.0f});
}

bool Pass::beginGroup(const DisplayGroup& group)
{
    const TQ3DisplayGroupState state = group.state();
    if ((state & kQ3DisplayGroupStateMaskIsDrawn) == 0)
        return false;
    if (m_groups.size() >= limits::kMaxGroupNesting)
        fail(kQ3ErrorInvalidObject, "display groups nest deeper than kQ3GroupMaxNesting (" +
                                        std::to_string(limits::kMaxGroupNesting) + ")");
    if (m_cullGroups && (state & kQ3DisplayGroupStateMaskUseBoundingBox) != 0 && group.boundingBox() &&
        !enterBoundedGroup(group, *group.boundingBox()))
        return false;
    const bool pushes = (state & kQ3DisplayGroupStateMaskIsInline) == 0;
    if (pushes)
        push();
    m_groups.push_back(GroupEntry{pushes, m_stack.size()});
    return true;
}

void Pass::endGroup(const DisplayGroup&)
{
    const GroupEntry entry = m_groups.back();
    m_groups.pop_back();
    // Pushes the group's objects left unmatched end with it.
    m_stack.resize(entry.floor);
    if (entry.pushed)
        pop();
}

bool Pass::enterBoundedGroup(const DisplayGroup&, const TQ3BoundingBox& box)
{
    return boxVisible(box);
}

bool Pass::boxVisible(const TQ3BoundingBox& box) const
{
    if (!m_window || enumValue(box.isEmpty) != kQ3False)
        return !m_window || enumValue(box.isEmpty) == kQ3False;
    // Outside when all eight corners are beyond the same clip plane.
    const Matrix toFrustum = then(m_state.localToWorld, m_window->worldToFrustum);
    int outside[6] = {0, 0, 0, 0, 0, 0};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                           (corner & 4) ? box.max.z : box.min.z);
        const glm::dvec4 v = transformPoint(toFrustum, p);
        // Frustum: x and y in [-w, w], z in [-w, 0] (QuickDraw 3D's frustum).
        outside[0] += v.x < -v.w;
        outside[1] += v.x > v.w;
        outside[2] += v.y < -v.w;
        outside[3] += v.y > v.w;
        outside[4] += v.z < -v.w;
        outside[5] += v.z > 0.0;
    }
    for (int count : outside)
        if (count == 8)
            return false;
    return true;
}

} // namespace q3
