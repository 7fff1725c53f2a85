// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "shader/IlluminationShaders.h"

namespace q3 {

const ClassInfo kPhongIlluminationClass{kQ3IlluminationTypePhong, &kIlluminationShaderClass,
                                        "Phong illumination shader"};
const ClassInfo kLambertIlluminationClass{kQ3IlluminationTypeLambert, &kIlluminationShaderClass,
                                          "Lambert illumination shader"};
const ClassInfo kNULLIlluminationClass{kQ3IlluminationTypeNULL, &kIlluminationShaderClass,
                                       "NULL illumination shader"};

} // namespace q3
