// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "style/Style.h"

namespace q3 {

/// A style whose data is one value (an enumeration, a Boolean, a mask, an
/// ID, or a small structure such as TQ3FogStyleData) that it copies into
/// one DrawState field. A Rule describes the style:
///   using Value = ...;                        the value's C type
///   static constexpr TQ3ObjectType kType;     the style's type code
///   static constexpr Value DrawState::*kField; the field apply() sets
///   static const ClassInfo& classInfo();
///   static Value check(const Value& value);   the rules of QD3DStyle.h:
///       throws (kQ3ErrorInvalidParameter) or returns the value to store
/// Invariant: the stored value is one Rule::check returned, so New, Set
/// and immediate-mode Submit can never disagree.
template <class Rule>
class ValueStyle final : public Style {
public:
    using Value = typename Rule::Value;
    static constexpr TQ3ObjectType kClassType = Rule::kType;

    /// Checks the value first; `value` may be a C caller's enum holding any int.
    explicit ValueStyle(const Value& value) : m_value(Rule::check(value)) {}

    const ClassInfo& classInfo() const override { return Rule::classInfo(); }
    Object* duplicate() const override { return makeShared<ValueStyle>(m_value).detach(); }
    void apply(DrawState& state) const override { state.*Rule::kField = m_value; }

    const Value& value() const { return m_value; }
    /// Checks, then stores and marks the edit; on failure nothing changes.
    void setValue(const Value& value)
    {
        m_value = Rule::check(value);
        markEdited();
    }

private:
    Value m_value;
};

} // namespace q3
