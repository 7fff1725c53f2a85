// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3PickIDStyle_New(unsigned long id)
{
    return newStyle<PickIDStyle>(__func__, id);
}

TQ3Status Q3PickIDStyle_Submit(unsigned long id, TQ3ViewObject view)
{
    return submitStyle<PickIDStyle>(__func__, id, view);
}

TQ3Status Q3PickIDStyle_Get(TQ3StyleObject pickIDObject, unsigned long* id)
{
    return getStyle<PickIDStyle>(__func__, pickIDObject, "pickIDObject", id, "id");
}

TQ3Status Q3PickIDStyle_Set(TQ3StyleObject pickIDObject, unsigned long id)
{
    return setStyle<PickIDStyle>(__func__, pickIDObject, "pickIDObject", id);
}

} // extern "C"
