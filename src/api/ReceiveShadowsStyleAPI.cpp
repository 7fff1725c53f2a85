// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3ReceiveShadowsStyle_New(TQ3Boolean receives)
{
    return newStyle<ReceiveShadowsStyle>(__func__, receives);
}

TQ3Status Q3ReceiveShadowsStyle_Submit(TQ3Boolean receives, TQ3ViewObject view)
{
    return submitStyle<ReceiveShadowsStyle>(__func__, receives, view);
}

TQ3Status Q3ReceiveShadowsStyle_Get(TQ3StyleObject styleObject, TQ3Boolean* receives)
{
    return getStyle<ReceiveShadowsStyle>(__func__, styleObject, "styleObject", receives, "receives");
}

TQ3Status Q3ReceiveShadowsStyle_Set(TQ3StyleObject styleObject, TQ3Boolean receives)
{
    return setStyle<ReceiveShadowsStyle>(__func__, styleObject, "styleObject", receives);
}

} // extern "C"
