// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Q3IlluminationShader_ and the constructors of its three kinds, which are
// one line each (Q3PhongIllumination_, Q3LambertIllumination_,
// Q3NULLIllumination_ have no other calls).

#include "QD3DShader.h"
#include "api/Entry.h"
#include "shader/IlluminationShaders.h"

using namespace q3;
using q3::api::guard;

namespace {

template <class T>
TQ3ShaderObject newIllumination(const char* function)
{
    return guard(function, TQ3ShaderObject{nullptr}, []() -> TQ3ShaderObject { return makeShared<T>().detach(); });
}

} // namespace

extern "C" {

TQ3ObjectType Q3IlluminationShader_GetType(TQ3ShaderObject shader)
{
    return api::getLeafType<IlluminationShader>(__func__, shader, "shader");
}

TQ3ShaderObject Q3PhongIllumination_New(void)
{
    return newIllumination<PhongIllumination>(__func__);
}

TQ3ShaderObject Q3LambertIllumination_New(void)
{
    return newIllumination<LambertIllumination>(__func__);
}

TQ3ShaderObject Q3NULLIllumination_New(void)
{
    return newIllumination<NULLIllumination>(__func__);
}

} // extern "C"
