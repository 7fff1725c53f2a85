// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/Entry.h"
#include "style/SubdivisionStyle.h"
#include "view/View.h"

using namespace q3;
using namespace q3::api;

extern "C" {

TQ3StyleObject Q3SubdivisionStyle_New(const TQ3SubdivisionStyleData* data)
{
    return newShared<SubdivisionStyle>(__func__, data, "data");
}

TQ3Status Q3SubdivisionStyle_Submit(const TQ3SubdivisionStyleData* data, TQ3ViewObject view)
{
    return guardStatus(__func__, [&] {
        requireNonNull(data, "data");
        ShapeVisitor& target = lookup<View>(view, "view").submitTarget();
        const Ref<SubdivisionStyle> style = makeShared<SubdivisionStyle>(*data);
        target.visitStyle(*style);
    });
}

TQ3Status Q3SubdivisionStyle_SetData(TQ3StyleObject subdiv, const TQ3SubdivisionStyleData* data)
{
    return setValue<SubdivisionStyle>(__func__, subdiv, "subdiv", data, "data", &SubdivisionStyle::setData);
}

TQ3Status Q3SubdivisionStyle_GetData(TQ3StyleObject subdiv, TQ3SubdivisionStyleData* data)
{
    return getValue<SubdivisionStyle>(__func__, subdiv, "subdiv", data, "data",
                                      [&](const SubdivisionStyle& style) { return style.data(); });
}

} // extern "C"
