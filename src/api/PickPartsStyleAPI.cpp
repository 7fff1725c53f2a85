// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3PickPartsStyle_New(TQ3PickParts parts)
{
    return newStyle<PickPartsStyle>(__func__, parts);
}

TQ3Status Q3PickPartsStyle_Submit(TQ3PickParts parts, TQ3ViewObject view)
{
    return submitStyle<PickPartsStyle>(__func__, parts, view);
}

TQ3Status Q3PickPartsStyle_Get(TQ3StyleObject pickPartsObject, TQ3PickParts* parts)
{
    return getStyle<PickPartsStyle>(__func__, pickPartsObject, "pickPartsObject", parts, "parts");
}

TQ3Status Q3PickPartsStyle_Set(TQ3StyleObject pickPartsObject, TQ3PickParts parts)
{
    return setStyle<PickPartsStyle>(__func__, pickPartsObject, "pickPartsObject", parts);
}

} // extern "C"
