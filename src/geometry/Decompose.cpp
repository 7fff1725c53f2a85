// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "geometry/Decompose.h"

#include "base/DrawState.h"
#include "core/ErrorManager.h"
#include "core/ParameterChecks.h"

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

std::string subdivisionWarning(const SubdivisionMeasure& measure, const SubdivisionShortfall& shortfall)
{
    std::string message = std::string(subdivisionMethodName(measure.method)) + " subdivision of " + shortfall.shape +
                          " with c1 = " + numberText(measure.options.c1);
    if (shortfall.withC2)
        message += " and c2 = " + numberText(measure.options.c2);
    message += " would need more than " + shortfall.limit + "; " + shortfall.used;
    return message;
}

void postSubdivisionWarning(const SubdivisionMeasure& measure, const SubdivisionShortfall& shortfall)
{
    errors::postWarning(kQ3WarningParameterOutOfRange, subdivisionWarning(measure, shortfall));
}

} // namespace q3
