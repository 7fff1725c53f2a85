// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// QD3DShader.h's colour routines (Q3ColorRGB_, and Q3ColorARGB_Set, the one
// ARGB routine): pointer checks, then the whole result computed before it
// is stored, as QD3DMath.h's routines do (api/MathEntry.h).

#include "QD3DShader.h"
#include "api/MathEntry.h"

using q3::api::computeInto;

namespace {

TQ3ColorRGB rgb(float r, float g, float b)
{
    return TQ3ColorRGB{r, g, b};
}

// A channel brought into 0..1; NaN stays NaN (neither comparison holds).
float clamp01(float c)
{
    return c < 0.0f ? 0.0f : c > 1.0f ? 1.0f : c;
}

} // namespace

extern "C" {

TQ3ColorRGB* Q3ColorRGB_Set(TQ3ColorRGB* color, float r, float g, float b)
{
    return computeInto(__func__, {{color, "color"}}, color, [&] { return rgb(r, g, b); });
}

TQ3ColorARGB* Q3ColorARGB_Set(TQ3ColorARGB* color, float a, float r, float g, float b)
{
    return computeInto(__func__, {{color, "color"}}, color, [&] { return TQ3ColorARGB{a, r, g, b}; });
}

TQ3ColorRGB* Q3ColorRGB_Add(const TQ3ColorRGB* c1, const TQ3ColorRGB* c2, TQ3ColorRGB* result)
{
    return computeInto(__func__, {{c1, "c1"}, {c2, "c2"}, {result, "result"}}, result,
                       [&] { return rgb(c1->r + c2->r, c1->g + c2->g, c1->b + c2->b); });
}

TQ3ColorRGB* Q3ColorRGB_Subtract(const TQ3ColorRGB* c1, const TQ3ColorRGB* c2, TQ3ColorRGB* result)
{
    return computeInto(__func__, {{c1, "c1"}, {c2, "c2"}, {result, "result"}}, result,
                       [&] { return rgb(c1->r - c2->r, c1->g - c2->g, c1->b - c2->b); });
}

TQ3ColorRGB* Q3ColorRGB_Scale(const TQ3ColorRGB* color, float scale, TQ3ColorRGB* result)
{
    return computeInto(__func__, {{color, "color"}, {result, "result"}}, result,
                       [&] { return rgb(color->r * scale, color->g * scale, color->b * scale); });
}

TQ3ColorRGB* Q3ColorRGB_Clamp(const TQ3ColorRGB* color, TQ3ColorRGB* result)
{
    return computeInto(__func__, {{color, "color"}, {result, "result"}}, result,
                       [&] { return rgb(clamp01(color->r), clamp01(color->g), clamp01(color->b)); });
}

TQ3ColorRGB* Q3ColorRGB_Lerp(const TQ3ColorRGB* first, const TQ3ColorRGB* last, float alpha, TQ3ColorRGB* result)
{
    return computeInto(__func__, {{first, "first"}, {last, "last"}, {result, "result"}}, result, [&] {
        return rgb(first->r + alpha * (last->r - first->r), first->g + alpha * (last->g - first->g),
                   first->b + alpha * (last->b - first->b));
    });
}

TQ3ColorRGB* Q3ColorRGB_Accumulate(const TQ3ColorRGB* src, TQ3ColorRGB* result)
{
    return computeInto(__func__, {{src, "src"}, {result, "result"}}, result,
                       [&] { return rgb(result->r + src->r, result->g + src->g, result->b + src->b); });
}

float* Q3ColorRGB_Luminance(const TQ3ColorRGB* color, float* luminance)
{
    return computeInto(__func__, {{color, "color"}, {luminance, "luminance"}}, luminance,
                       [&] { return 0.30078125f * color->r + 0.58984375f * color->g + 0.109375f * color->b; });
}

} // extern "C"
