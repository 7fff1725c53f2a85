// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "light/Light.h"

namespace q3 {

const ClassInfo kLightClass{kQ3ShapeTypeLight, &kShapeClass, "light"};

} // namespace q3
