// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Decompose.h"

#include "core/ErrorManager.h"

#include <cstdio>

namespace q3 {

std::vector<double> SubdivisionMeasure::key() const
{
    const nurbs::TessellationOptions& o = options;
    std::vector<double> values{double(method), o.c1, o.c2, double(o.maxSegments)};
    if (o.method == nurbs::Method::kAdaptive) {
        for (const auto& row : o.mapping.matrix)
            values.insert(values.end(), row, row + 4);
        values.insert(values.end(), o.mapping.scale, o.mapping.scale + 3);
        values.push_back(o.mapping.requirePositiveW ? 1.0 : 0.0);
        values.push_back(o.mapping.clipNearer ? 1.0 : 0.0);
    }
    values.push_back(o.hasClip && o.coarseOutsideClip ? 1.0 : 0.0);
    if (o.hasClip && o.coarseOutsideClip)
        values.insert(values.end(), o.clip.begin(), o.clip.end());
    return values;
}

namespace {

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

const char* methodName(TQ3SubdivisionMethod method)
{
    switch (method) {
    case kQ3SubdivisionMethodConstant:
        return "constant";
    case kQ3SubdivisionMethodWorldSpace:
        return "world-space";
    case kQ3SubdivisionMethodScreenSpace:
        break;
    }
    return "screen-space";
}

} // namespace

std::string subdivisionWarning(const SubdivisionMeasure& measure, const SubdivisionShortfall& shortfall)
{
    std::string message = std::string(methodName(measure.method)) + " subdivision of " + shortfall.shape +
                          " with c1 = " + number(measure.options.c1);
    if (shortfall.withC2)
        message += " and c2 = " + number(measure.options.c2);
    message += " would need more than " + shortfall.limit + "; " + shortfall.used;
    return message;
}

void postSubdivisionWarning(const SubdivisionMeasure& measure, const SubdivisionShortfall& shortfall)
{
    errors::postWarning(kQ3WarningParameterOutOfRange, subdivisionWarning(measure, shortfall));
}

} // namespace q3
