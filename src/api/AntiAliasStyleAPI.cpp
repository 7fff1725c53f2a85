// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3AntiAliasStyle_New(const TQ3AntiAliasStyleData* data)
{
    return newStyle<AntiAliasStyle>(__func__, data);
}

TQ3Status Q3AntiAliasStyle_Submit(const TQ3AntiAliasStyleData* data, TQ3ViewObject view)
{
    return submitStyle<AntiAliasStyle>(__func__, data, view);
}

TQ3Status Q3AntiAliasStyle_GetData(TQ3StyleObject styleObject, TQ3AntiAliasStyleData* data)
{
    return getStyle<AntiAliasStyle>(__func__, styleObject, "styleObject", data, "data");
}

TQ3Status Q3AntiAliasStyle_SetData(TQ3StyleObject styleObject, const TQ3AntiAliasStyleData* data)
{
    return setStyle<AntiAliasStyle>(__func__, styleObject, data);
}

} // extern "C"
