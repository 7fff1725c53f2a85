// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#include "render/GlApi.h"

#include <cassert>

namespace q3 {
namespace {

thread_local const GlApi* t_current = nullptr;

} // namespace

bool GlApi::load(GetProcAddress getProcAddress, void* loader, const char*& missing)
{
    missing = nullptr;
#define Q3_GL_LOAD(name)                                                                       \
    name = reinterpret_cast<decltype(name)>(getProcAddress("gl" #name, loader));               \
    if (name == nullptr && missing == nullptr)                                                 \
        missing = "gl" #name;
    Q3_GL_FUNCTIONS(Q3_GL_LOAD)
#undef Q3_GL_LOAD
    return missing == nullptr;
}

const GlApi& gl()
{
    assert(t_current != nullptr && "a gl* call outside a GlApiScope");
    return *t_current;
}

GlApiScope::GlApiScope(const GlApi* api) : m_previous(t_current)
{
    t_current = api;
}

GlApiScope::~GlApiScope()
{
    t_current = m_previous;
}

} // namespace q3
