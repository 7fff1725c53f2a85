// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "view/Pass.h"

#include "core/AttributeSet.h"
#include "geometry/Geometry.h"
#include "shader/Shader.h"
#include "style/Style.h"
#include "view/Transform.h"

namespace q3 {

void Pass::visitAttributeSet(const AttributeSet& attributes)
{
    if (const std::optional<TQ3ColorRGB> color = attributes.diffuseColor())
        m_state.diffuseColor = *color;
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
    if (m_stack.empty())
        fail(kQ3ErrorNothingToPop, "no state pushed with Q3Push_Submit in this traversal is left to pop");
    m_state = m_stack.back();
    m_stack.pop_back();
}

TessellationSetting Pass::tessellationSetting() const
{
    TessellationSetting setting;
    setting.style = m_state.draw.subdivision;
    setting.localToWorld = m_state.localToWorld;
    setting.window = m_window;
    return setting;
}

void Pass::curvePolyline(const nurbs::CurveRef& curve, CurveCache* cache, const PolylineUser& use) const
{
    withCurvePolyline(curve, cache, tessellationSetting(), use);
}

SubdivisionMeasure Pass::subdivisionMeasure() const
{
    return measureFor(tessellationSetting());
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
    return m_state.diffuseColor;
}

} // namespace q3
