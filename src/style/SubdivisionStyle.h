// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

#include "QD3DStyle.h"
#include "style/Style.h"

namespace q3 {

extern const ClassInfo kSubdivisionStyleClass;

/// The view's subdivision style when none has been submitted: QuickDraw 3D's
/// default, screen space with c1 = c2 = 20 pixels.
TQ3SubdivisionStyleData defaultSubdivisionStyle();

/// The article's rule ("CONTROLLING SUBDIVISION"): both c1 and c2 are checked
/// whenever a style is created, changed or submitted, because a curve cannot
/// know whether a surface comes next. An unreasonable value is replaced by the
/// reasonable one documented in QD3DStyle.h and kQ3WarningParameterOutOfRange
/// is posted once for the call. A constant c1 keeps its fraction here (GetData
/// returns what was set); the tessellator truncates it. A method that is none
/// of the three throws kQ3ErrorInvalidData (there is no method to guess).
TQ3SubdivisionStyleData checkSubdivisionStyle(const TQ3SubdivisionStyleData& requested);

/// A retained subdivision style. Invariant: its data has passed
/// checkSubdivisionStyle, so it is always reasonable.
class SubdivisionStyle final : public Style {
public:
    static constexpr TQ3ObjectType kClassType = kQ3StyleTypeSubdivision;

    explicit SubdivisionStyle(const TQ3SubdivisionStyleData& data);

    const ClassInfo& classInfo() const override { return kSubdivisionStyleClass; }
    Object* duplicate() const override;
    void apply(DrawState& state) const override { state.subdivision = m_data; }

    const TQ3SubdivisionStyleData& data() const { return m_data; }
    void setData(const TQ3SubdivisionStyleData& data);

private:
    TQ3SubdivisionStyleData m_data;
};

} // namespace q3
