// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3InterpolationStyle_New(TQ3InterpolationStyle interpolationStyle)
{
    return newStyle<InterpolationStyle>(__func__, interpolationStyle);
}

TQ3Status Q3InterpolationStyle_Submit(TQ3InterpolationStyle interpolationStyle, TQ3ViewObject view)
{
    return submitStyle<InterpolationStyle>(__func__, interpolationStyle, view);
}

TQ3Status Q3InterpolationStyle_Get(TQ3StyleObject interpolationObject, TQ3InterpolationStyle* interpolationStyle)
{
    return getStyle<InterpolationStyle>(__func__, interpolationObject, "interpolationObject", interpolationStyle,
                                        "interpolationStyle");
}

TQ3Status Q3InterpolationStyle_Set(TQ3StyleObject interpolationObject, TQ3InterpolationStyle interpolationStyle)
{
    return setStyle<InterpolationStyle>(__func__, interpolationObject, "interpolationObject", interpolationStyle);
}

} // extern "C"
