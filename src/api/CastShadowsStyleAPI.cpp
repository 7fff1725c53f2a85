// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3CastShadowsStyle_New(TQ3Boolean castsShadows)
{
    return newStyle<CastShadowsStyle>(__func__, castsShadows);
}

TQ3Status Q3CastShadowsStyle_Submit(TQ3Boolean castShadows, TQ3ViewObject view)
{
    return submitStyle<CastShadowsStyle>(__func__, castShadows, view);
}

TQ3Status Q3CastShadowsStyle_Get(TQ3StyleObject styleObject, TQ3Boolean* castShadows)
{
    return getStyle<CastShadowsStyle>(__func__, styleObject, "styleObject", castShadows, "castShadows");
}

TQ3Status Q3CastShadowsStyle_Set(TQ3StyleObject styleObject, TQ3Boolean castShadows)
{
    return setStyle<CastShadowsStyle>(__func__, styleObject, "styleObject", castShadows);
}

} // extern "C"
