// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// Group classes applications register (QD3DGroup.h's group extension
// methods): a class registered under a group class is a group of that kind
// whose class may replace what Q3 does for its groups. Which method replaces
// what is in docs/extensions.md, "Group classes".

#include "QD3DGroup.h"
#include "group/Group.h"

namespace q3 {

/// The method of that type that the class of `group` gives (a class an
/// application registered), or null: for a group of a class Q3 defines, a
/// class that gives none, and while that same method runs for that group on
/// this thread (a GroupMethodCall), so that a method calling the Q3Group_
/// function it replaces gets Q3's own behaviour, as a parent's method.
TQ3XFunctionPointer groupMethod(const Group& group, TQ3XMethodType type);

/// Marks a group method running for a group on this thread.
class GroupMethodCall {
public:
    GroupMethodCall(const Group& group, TQ3XMethodType type);
    ~GroupMethodCall();
    GroupMethodCall(const GroupMethodCall&) = delete;
    GroupMethodCall& operator=(const GroupMethodCall&) = delete;
};

/// Q3XGroup_GetPositionPrivate: the private data of one of the group's
/// positions. Throws kQ3ErrorInvalidPositionForGroup for a position not of
/// the group, kQ3ErrorInvalidObjectClass when the group's class keeps no
/// data per position (kQ3XMethodType_GroupPositionSize 0, no new method).
void* positionPrivate(Group& group, TQ3GroupPosition position);

} // namespace q3
