// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "style/SubdivisionStyle.h"

#include "core/EnumValue.h"
#include "core/Limits.h"
#include "core/ErrorManager.h"
#include "core/ShapeVisitor.h"

#include <cmath>
#include <string>

namespace q3 {

const ClassInfo kSubdivisionStyleClass{kQ3StyleTypeSubdivision, &kStyleClass, "subdivision style"};

namespace {

// One parameter (c1 or c2) under QD3DStyle.h's substitution rule: returns the
// value to use and appends to `report` when it replaced an unreasonable one.
float checkParameter(TQ3SubdivisionMethod method, float value, const char* name, std::string& report)
{
    float result = value;
    const char* why = nullptr;
    if (!std::isfinite(value)) {
        result = limits::kSubdivisionDefault;
        why = "is not finite";
    } else if (method == kQ3SubdivisionMethodConstant) {
        if (value < 1.0f) {
            result = 1.0f;
            why = "is less than one segment per span";
        } else if (value > static_cast<float>(limits::kMaxConstantSegments)) {
            result = static_cast<float>(limits::kMaxConstantSegments);
            why = "asks for more than kQ3SubdivisionMaxConstantSegments segments per span";
        }
    } else if (value <= 0.0f) {
        result = limits::kSubdivisionDefault;
        why = "is not a positive length";
    } else if (method == kQ3SubdivisionMethodScreenSpace && value < limits::kMinScreenSpaceC1) {
        result = limits::kMinScreenSpaceC1;
        why = "is below kQ3SubdivisionMinScreenSpaceC1 (1/8 pixel, finer than the pane is sampled)";
    }
    if (why != nullptr) {
        if (!report.empty())
            report += "; ";
        report += std::string(name) + " = " + std::to_string(value) + " " + why + " for the " +
                  subdivisionMethodName(method) + " method, so " + std::to_string(result) + " is used";
    }
    return result;
}

} // namespace

TQ3SubdivisionStyleData defaultSubdivisionStyle()
{
    return {kQ3SubdivisionMethodScreenSpace, limits::kSubdivisionDefault, limits::kSubdivisionDefault};
}

TQ3SubdivisionStyleData checkSubdivisionStyle(const TQ3SubdivisionStyleData& requested)
{
    const long method = enumValue(requested.method); // a C caller may store any int
    if (method < kQ3SubdivisionMethodConstant || method > kQ3SubdivisionMethodScreenSpace)
        fail(kQ3ErrorInvalidData,
             "subdivision method " + std::to_string(method) +
                 " is none of kQ3SubdivisionMethodConstant, WorldSpace, ScreenSpace");
    TQ3SubdivisionStyleData result = requested;
    std::string report;
    result.c1 = checkParameter(requested.method, requested.c1, "c1", report);
    result.c2 = checkParameter(requested.method, requested.c2, "c2", report);
    if (!report.empty())
        errors::postWarning(kQ3WarningParameterOutOfRange, "subdivision style: " + report);
    return result;
}

SubdivisionStyle::SubdivisionStyle(const TQ3SubdivisionStyleData& data)
    : m_data(checkSubdivisionStyle(data))
{
}

Object* SubdivisionStyle::duplicate() const
{
    return makeShared<SubdivisionStyle>(m_data).detach();
}

void SubdivisionStyle::setData(const TQ3SubdivisionStyleData& data)
{
    m_data = checkSubdivisionStyle(data);
    markEdited();
}

} // namespace q3
