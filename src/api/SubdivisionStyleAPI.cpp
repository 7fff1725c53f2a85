// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "QD3DStyle.h"
#include "api/Entry.h"
#include "style/SubdivisionStyle.h"
#include "view/View.h"

using namespace q3;
using q3::api::guard;
using q3::api::guardStatus;

extern "C" {

TQ3StyleObject Q3SubdivisionStyle_New(const TQ3SubdivisionStyleData* data)
{
    return guard(__func__, TQ3StyleObject{nullptr}, [&]() -> TQ3StyleObject {
        requireNonNull(data, "data");
        return makeShared<SubdivisionStyle>(*data).detach();
    });
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
    return guardStatus(__func__, [&] {
        SubdivisionStyle& style = lookup<SubdivisionStyle>(subdiv, "subdiv");
        requireNonNull(data, "data");
        style.setData(*data);
    });
}

TQ3Status Q3SubdivisionStyle_GetData(TQ3StyleObject subdiv, TQ3SubdivisionStyleData* data)
{
    return guardStatus(__func__, [&] {
        const SubdivisionStyle& style = lookup<SubdivisionStyle>(subdiv, "subdiv");
        requireNonNull(data, "data");
        *data = style.data();
    });
}

} // extern "C"
