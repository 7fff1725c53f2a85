// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/StyleEntry.h"
#include "style/ValueStyles.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3BackfacingStyle_New(TQ3BackfacingStyle backfacingStyle)
{
    return newStyle<BackfacingStyle>(__func__, backfacingStyle);
}

TQ3Status Q3BackfacingStyle_Submit(TQ3BackfacingStyle backfacingStyle, TQ3ViewObject view)
{
    return submitStyle<BackfacingStyle>(__func__, backfacingStyle, view);
}

TQ3Status Q3BackfacingStyle_Get(TQ3StyleObject backfacingObject, TQ3BackfacingStyle* backfacingStyle)
{
    return getStyle<BackfacingStyle>(__func__, backfacingObject, "backfacingObject", backfacingStyle,
                                     "backfacingStyle");
}

TQ3Status Q3BackfacingStyle_Set(TQ3StyleObject backfacingObject, TQ3BackfacingStyle backfacingStyle)
{
    return setStyle<BackfacingStyle>(__func__, backfacingObject, "backfacingObject", backfacingStyle);
}

} // extern "C"
