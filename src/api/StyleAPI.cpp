// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/Entry.h"
#include "style/Style.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3ObjectType Q3Style_GetType(TQ3StyleObject style)
{
    return api::getLeafType<Style>(__func__, style, "style");
}

TQ3Status Q3Style_Submit(TQ3StyleObject style, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        const Style& source = lookup<Style>(style, "style");
        lookup<View>(view, "view").submit(source);
    });
}

} // extern "C"
