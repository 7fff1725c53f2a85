// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3FillStyle_New(TQ3FillStyle fillStyle)
{
    return newStyle<FillStyle>(__func__, fillStyle);
}

TQ3Status Q3FillStyle_Submit(TQ3FillStyle fillStyle, TQ3ViewObject view)
{
    return submitStyle<FillStyle>(__func__, fillStyle, view);
}

TQ3Status Q3FillStyle_Get(TQ3StyleObject styleObject, TQ3FillStyle* fillStyle)
{
    return getStyle<FillStyle>(__func__, styleObject, "styleObject", fillStyle, "fillStyle");
}

TQ3Status Q3FillStyle_Set(TQ3StyleObject styleObject, TQ3FillStyle fillStyle)
{
    return setStyle<FillStyle>(__func__, styleObject, "styleObject", fillStyle);
}

} // extern "C"
