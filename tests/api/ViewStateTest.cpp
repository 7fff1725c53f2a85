// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// The graphics state of a traversal: local-to-world matrix and subdivision
// style, Q3Push_Submit / Q3Pop_Submit, and the reset at every loop start.

#include "RenderTestSupport.h"

#include "QD3DSet.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"

#include <memory>

namespace {

using namespace q3test;

class ViewStateTest : public TestViewApiTest {
protected:
    ViewStateTest() : TestViewApiTest(32, 24) {}

    TQ3Matrix4x4 matrixState()
    {
        TQ3Matrix4x4 matrix{};
        EXPECT_EQ(Q3View_GetLocalToWorldMatrixState(view(), &matrix), kQ3Success);
        return matrix;
    }

    TQ3SubdivisionStyleData styleState()
    {
        TQ3SubdivisionStyleData style{};
        EXPECT_EQ(Q3View_GetSubdivisionStyleState(view(), &style), kQ3Success);
        return style;
    }

    static void expectIdentity(const TQ3Matrix4x4& m)
    {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                EXPECT_EQ(m.value[i][j], i == j ? 1.0f : 0.0f) << i << ", " << j;
    }

    static void expectDefaultStyle(const TQ3SubdivisionStyleData& style)
    {
        EXPECT_EQ(style.method, kQ3ViewDefaultSubdivisionMethod);
        EXPECT_EQ(style.c1, float(kQ3ViewDefaultSubdivisionC1));
        EXPECT_EQ(style.c2, float(kQ3ViewDefaultSubdivisionC2));
    }
};

TEST_F(ViewStateTest, EveryLoopStartsFromTheDefaultState)
{
    for (int loop = 0; loop < 3; ++loop) {
        if (loop == 0)
            ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
        else if (loop == 1)
            ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
        else
            ASSERT_EQ(Q3View_StartBoundingSphere(view(), kQ3ComputeBoundsApproximate), kQ3Success);
        expectIdentity(matrixState());
        expectDefaultStyle(styleState());
        // Change everything, and leave a state pushed, before ending.
        const TQ3Vector3D offset = {1, 2, 3};
        const TQ3SubdivisionStyleData constant = {kQ3SubdivisionMethodConstant, 3, 3};
        Q3TranslateTransform_Submit(&offset, view());
        Q3SubdivisionStyle_Submit(&constant, view());
        Q3Push_Submit(view());
        if (loop == 0) {
            EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
        } else if (loop == 1) {
            TQ3BoundingBox box;
            EXPECT_EQ(Q3View_EndBoundingBox(view(), &box), kQ3ViewStatusDone);
        } else {
            TQ3BoundingSphere sphere;
            EXPECT_EQ(Q3View_EndBoundingSphere(view(), &sphere), kQ3ViewStatusDone);
        }
    }
    // States pushed in an earlier traversal are gone.
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    EXPECT_Q3_ERROR(Q3Pop_Submit(view()), kQ3ErrorNothingToPop);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
}

TEST_F(ViewStateTest, SubdivisionStyleStateIsTheLastSubmittedAfterSubstitution)
{
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    const TQ3SubdivisionStyleData world = {kQ3SubdivisionMethodWorldSpace, 0.25f, 0.5f};
    Q3SubdivisionStyle_Submit(&world, view());
    TQ3SubdivisionStyleData state = styleState();
    EXPECT_EQ(state.method, kQ3SubdivisionMethodWorldSpace);
    EXPECT_EQ(state.c1, 0.25f);
    EXPECT_EQ(state.c2, 0.5f);
    // An unreasonable c1 is replaced before the view records it.
    const TQ3SubdivisionStyleData tooFew = {kQ3SubdivisionMethodConstant, 0.5f, 2};
    EXPECT_Q3_WARNING(Q3SubdivisionStyle_Submit(&tooFew, view()), kQ3WarningParameterOutOfRange);
    state = styleState();
    EXPECT_EQ(state.method, kQ3SubdivisionMethodConstant);
    EXPECT_EQ(state.c1, 1.0f);
    EXPECT_EQ(state.c2, 2.0f);
    // A retained style object counts the same.
    const TQ3SubdivisionStyleData screen = {kQ3SubdivisionMethodScreenSpace, 7, 7};
    TQ3StyleObject styleObject = Q3SubdivisionStyle_New(&screen);
    EXPECT_EQ(Q3Object_Submit(styleObject, view()), kQ3Success);
    EXPECT_EQ(styleState().c1, 7.0f);
    // A style that fails (an unknown method) changes nothing.
    const TQ3SubdivisionStyleData bad = {TQ3SubdivisionMethod(3), 5, 5};
    EXPECT_Q3_ERROR(Q3SubdivisionStyle_Submit(&bad, view()), kQ3ErrorInvalidData);
    EXPECT_EQ(styleState().method, kQ3SubdivisionMethodScreenSpace);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
    Q3Object_Dispose(styleObject);
}

TEST_F(ViewStateTest, TransformsComposeInSubmissionOrder)
{
    ASSERT_EQ(Q3View_StartBoundingBox(view(), kQ3ComputeBoundsExact), kQ3Success);
    const TQ3Vector3D offset = {1, 2, 3};
    const TQ3Vector3D scale = {2, 2, 2};
    Q3TranslateTransform_Submit(&offset, view());
    Q3ScaleTransform_Submit(&scale, view());
    // A transform submitted later acts first on the geometry: a local point
    // p goes to p * S * T, so the translation is not scaled.
    TQ3Matrix4x4 m = matrixState();
    EXPECT_FLOAT_EQ(m.value[0][0], 2.0f);
    EXPECT_FLOAT_EQ(m.value[3][0], 1.0f);
    EXPECT_FLOAT_EQ(m.value[3][1], 2.0f);
    EXPECT_FLOAT_EQ(m.value[3][2], 3.0f);
    // The reset transform brings back the identity.
    EXPECT_EQ(Q3ResetTransform_Submit(view()), kQ3Success);
    expectIdentity(matrixState());
    TQ3BoundingBox box;
    EXPECT_EQ(Q3View_EndBoundingBox(view(), &box), kQ3ViewStatusDone);
}

TEST_F(ViewStateTest, PopRestoresWhatPushSaved)
{
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    const TQ3Vector3D offset = {1, 0, 0};
    const TQ3SubdivisionStyleData constant = {kQ3SubdivisionMethodConstant, 3, 3};
    Q3TranslateTransform_Submit(&offset, view());
    EXPECT_EQ(Q3Push_Submit(view()), kQ3Success);
    Q3TranslateTransform_Submit(&offset, view());
    Q3SubdivisionStyle_Submit(&constant, view());
    EXPECT_EQ(Q3Push_Submit(view()), kQ3Success);
    Q3TranslateTransform_Submit(&offset, view());
    EXPECT_FLOAT_EQ(matrixState().value[3][0], 3.0f);
    EXPECT_EQ(Q3Pop_Submit(view()), kQ3Success);
    EXPECT_FLOAT_EQ(matrixState().value[3][0], 2.0f);
    EXPECT_EQ(styleState().method, kQ3SubdivisionMethodConstant);
    EXPECT_EQ(Q3Pop_Submit(view()), kQ3Success);
    EXPECT_FLOAT_EQ(matrixState().value[3][0], 1.0f);
    expectDefaultStyle(styleState());
    // Nothing left: the pop fails and the state stays.
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3Pop_Submit(view()), kQ3Failure), kQ3ErrorNothingToPop);
    EXPECT_FLOAT_EQ(matrixState().value[3][0], 1.0f);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
}

TEST_F(ViewStateTest, PushAndPopWorkInBoundingLoopsToo)
{
    ASSERT_EQ(Q3View_StartBoundingSphere(view(), kQ3ComputeBoundsExact), kQ3Success);
    EXPECT_Q3_ERROR(Q3Pop_Submit(view()), kQ3ErrorNothingToPop);
    EXPECT_EQ(Q3Push_Submit(view()), kQ3Success);
    EXPECT_EQ(Q3Pop_Submit(view()), kQ3Success);
    TQ3BoundingSphere sphere;
    EXPECT_EQ(Q3View_EndBoundingSphere(view(), &sphere), kQ3ViewStatusDone);
}

TEST_F(ViewStateTest, StateCallsRejectBadArguments)
{
    ASSERT_EQ(Q3View_StartRendering(view()), kQ3Success);
    TQ3CameraObject camera = m_view->camera();
    TQ3Object dead = Q3AttributeSet_New();
    Q3Object_Dispose(dead);
    EXPECT_Q3_ERROR(EXPECT_EQ(Q3View_GetLocalToWorldMatrixState(view(), nullptr), kQ3Failure),
                    kQ3ErrorNULLParameter);
    TQ3Matrix4x4 matrix;
    EXPECT_Q3_ERROR(Q3View_GetLocalToWorldMatrixState(nullptr, &matrix), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetLocalToWorldMatrixState(camera, &matrix), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_GetLocalToWorldMatrixState(dead, &matrix), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3View_GetSubdivisionStyleState(view(), nullptr), kQ3ErrorNULLParameter);
    TQ3SubdivisionStyleData style;
    EXPECT_Q3_ERROR(Q3View_GetSubdivisionStyleState(nullptr, &style), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3View_GetSubdivisionStyleState(camera, &style), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3View_GetSubdivisionStyleState(dead, &style), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Push_Submit(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Push_Submit(camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Push_Submit(dead), kQ3ErrorInvalidObject);
    EXPECT_Q3_ERROR(Q3Pop_Submit(nullptr), kQ3ErrorNULLParameter);
    EXPECT_Q3_ERROR(Q3Pop_Submit(camera), kQ3ErrorInvalidObjectType);
    EXPECT_Q3_ERROR(Q3Pop_Submit(dead), kQ3ErrorInvalidObject);
    EXPECT_EQ(Q3View_EndRendering(view()), kQ3ViewStatusDone);
}

} // namespace
