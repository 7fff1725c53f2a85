// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DStyle.h"
#include "core/AttributeSet.h"
#include "style/Style.h"

namespace q3 {

extern const ClassInfo kHighlightStyleClass;

/// The highlight style: the attribute set drawn over the attributes of
/// geometries whose highlight state is on. Invariant: it holds one reference
/// to its set, or none (null: highlighting off, the view's default).
class HighlightStyle final : public Style {
public:
    static constexpr TQ3ObjectType kClassType = kQ3StyleTypeHighlight;

    explicit HighlightStyle(Ref<AttributeSet> attributes) : m_attributes(std::move(attributes)) {}

    const ClassInfo& classInfo() const override { return kHighlightStyleClass; }
    /// A copy with a copy of the attribute set, not a second reference to it.
    Object* duplicate() const override;
    void apply(DrawState& state) const override { state.highlight = m_attributes; }

    const Ref<AttributeSet>& attributes() const { return m_attributes; }
    void setAttributes(Ref<AttributeSet> attributes);

private:
    Ref<AttributeSet> m_attributes;
};

} // namespace q3
