// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3FogStyle_New(const TQ3FogStyleData* data)
{
    return newStyle<FogStyle>(__func__, data);
}

TQ3Status Q3FogStyle_Submit(const TQ3FogStyleData* data, TQ3ViewObject view)
{
    return submitStyle<FogStyle>(__func__, data, view);
}

TQ3Status Q3FogStyle_GetData(TQ3StyleObject styleObject, TQ3FogStyleData* data)
{
    return getStyle<FogStyle>(__func__, styleObject, "styleObject", data, "data");
}

TQ3Status Q3FogStyle_SetData(TQ3StyleObject styleObject, const TQ3FogStyleData* data)
{
    return setStyle<FogStyle>(__func__, styleObject, data);
}

} // extern "C"
