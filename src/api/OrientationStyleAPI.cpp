// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3OrientationStyle_New(TQ3OrientationStyle frontFacingDirection)
{
    return newStyle<OrientationStyle>(__func__, frontFacingDirection);
}

TQ3Status Q3OrientationStyle_Submit(TQ3OrientationStyle frontFacingDirection, TQ3ViewObject view)
{
    return submitStyle<OrientationStyle>(__func__, frontFacingDirection, view);
}

TQ3Status Q3OrientationStyle_Get(TQ3StyleObject frontFacingDirectionObject, TQ3OrientationStyle* frontFacingDirection)
{
    return getStyle<OrientationStyle>(__func__, frontFacingDirectionObject, "frontFacingDirectionObject",
                                      frontFacingDirection, "frontFacingDirection");
}

TQ3Status Q3OrientationStyle_Set(TQ3StyleObject frontFacingDirectionObject, TQ3OrientationStyle frontFacingDirection)
{
    return setStyle<OrientationStyle>(__func__, frontFacingDirectionObject, "frontFacingDirectionObject",
                                      frontFacingDirection);
}

} // extern "C"
