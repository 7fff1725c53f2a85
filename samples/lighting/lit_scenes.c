/* SPDX-License-Identifier: MIT */
/* Copyright (c) 2026 The Q3 authors */
#include "lit_scenes.h"
#include "scene_util.h"

#include "QD3DGeometry.h"
#include "QD3DGroup.h"
#include "QD3DLight.h"
#include "QD3DRenderer.h"
#include "QD3DSet.h"
#include "QD3DShader.h"
#include "QD3DStyle.h"
#include "QD3DTransform.h"
#include "QD3DView.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* ---- Helpers ------------------------------------------------------------- */

/* A diffuse colour, and a specular colour and control for Phong. */
static TQ3AttributeSet surface_set(TQ3ColorRGB diffuse)
{
    TQ3AttributeSet set = Q3AttributeSet_New();
    TQ3ColorRGB white = rgb(1.0f, 1.0f, 1.0f);
    float control = 15.0f;
    if (set != NULL && (Q3AttributeSet_Add(set, kQ3AttributeTypeDiffuseColor, &diffuse) != kQ3Success ||
                        Q3AttributeSet_Add(set, kQ3AttributeTypeSpecularColor, &white) != kQ3Success ||
                        Q3AttributeSet_Add(set, kQ3AttributeTypeSpecularControl, &control) != kQ3Success)) {
        Q3Object_Dispose(set);
        set = NULL;
    }
    return set;
}

static TQ3GeometryObject new_sphere(TQ3Point3D centre, float radius, TQ3AttributeSet set)
{
    TQ3EllipsoidData data;
    memset(&data, 0, sizeof data);
    data.origin = centre;
    data.orientation = vector3(0, radius, 0);
    data.majorRadius = vector3(0, 0, radius);
    data.minorRadius = vector3(radius, 0, 0);
    data.uMax = data.vMax = 1.0f;
    data.ellipsoidAttributeSet = set;
    return Q3Ellipsoid_New(&data);
}

/* A torus around the y axis, or around the z axis (facing the camera). */
static TQ3GeometryObject new_torus(TQ3Point3D centre, float ring, float tube, int facing, TQ3AttributeSet set)
{
    TQ3TorusData data;
    memset(&data, 0, sizeof data);
    data.origin = centre;
    data.orientation = facing ? vector3(0, 0, tube) : vector3(0, tube, 0);
    data.majorRadius = facing ? vector3(ring, 0, 0) : vector3(0, 0, ring);
    data.minorRadius = facing ? vector3(0, ring, 0) : vector3(ring, 0, 0);
    data.ratio = 1.0f;
    data.uMax = data.vMax = 1.0f;
    data.torusAttributeSet = set;
    return Q3Torus_New(&data);
}

static TQ3GeometryObject new_box(TQ3Point3D corner, float size, TQ3AttributeSet set)
{
    TQ3BoxData data;
    memset(&data, 0, sizeof data);
    data.origin = corner;
    data.orientation = vector3(0, size, 0);
    data.majorAxis = vector3(0, 0, size);
    data.minorAxis = vector3(size, 0, 0);
    data.boxAttributeSet = set;
    return Q3Box_New(&data);
}

/* A square floor at height y, counterclockwise seen from above. */
static TQ3GeometryObject new_floor(float y, float half, TQ3AttributeSet set)
{
    TQ3Vertex3D vertices[4];
    TQ3PolygonData data;
    memset(vertices, 0, sizeof vertices);
    vertices[0].point = point3(-half, y, half);
    vertices[1].point = point3(half, y, half);
    vertices[2].point = point3(half, y, -half);
    vertices[3].point = point3(-half, y, -half);
    data.numVertices = 4;
    data.vertices = vertices;
    data.polygonAttributeSet = set;
    return Q3Polygon_New(&data);
}

/* ---- Lights --------------------------------------------------------------- */

static TQ3LightData light_data(float brightness, TQ3ColorRGB color)
{
    TQ3LightData data;
    data.isOn = kQ3True;
    data.brightness = brightness;
    data.color = color;
    return data;
}

static int add_light(TQ3GroupObject group, TQ3LightObject light)
{
    int ok = light != NULL && Q3Group_AddObject(group, light) != NULL;
    dispose(light);
    return ok;
}

static int add_ambient(TQ3GroupObject group, float brightness)
{
    TQ3LightData data = light_data(brightness, rgb(1, 1, 1));
    return add_light(group, Q3AmbientLight_New(&data));
}

static int add_directional(TQ3GroupObject group, float brightness, TQ3Vector3D direction)
{
    TQ3DirectionalLightData data;
    data.lightData = light_data(brightness, rgb(1, 1, 1));
    data.castsShadows = kQ3False;
    data.direction = direction;
    return add_light(group, Q3DirectionalLight_New(&data));
}

static TQ3GroupObject finish(TQ3GroupObject group, int ok)
{
    if (!ok) {
        dispose(group);
        return NULL;
    }
    return group;
}

TQ3GroupObject q3litscene_new_lights(float ambient, float directional, TQ3Vector3D direction)
{
    TQ3GroupObject group = Q3LightGroup_New();
    return finish(group, group != NULL && add_ambient(group, ambient) &&
                             add_directional(group, directional, direction));
}

/* What QuickDraw 3D viewers lit a model with: a dim ambient light and a
 * directional light from the upper left, behind the viewer. */
static TQ3GroupObject lights_viewer(void)
{
    return q3litscene_new_lights(0.25f, 0.9f, vector3(0.6f, -0.5f, -0.6f));
}

static TQ3GroupObject lights_ambient(void)
{
    TQ3GroupObject group = Q3LightGroup_New();
    return finish(group, group != NULL && add_ambient(group, 0.7f));
}

static TQ3GroupObject lights_directional(void)
{
    return q3litscene_new_lights(0.15f, 1.0f, vector3(1.0f, -1.0f, -0.4f));
}

/* A warm point light above the front of the stage, fading with distance. */
static TQ3GroupObject lights_point(void)
{
    TQ3GroupObject group = Q3LightGroup_New();
    TQ3PointLightData data;
    data.lightData = light_data(2.2f, rgb(1.0f, 0.9f, 0.7f));
    data.castsShadows = kQ3False;
    data.attenuation = kQ3AttenuationTypeInverseDistance;
    data.location = point3(-0.5f, 1.6f, 1.2f);
    return finish(group, group != NULL && add_ambient(group, 0.1f) && add_light(group, Q3PointLight_New(&data)));
}

/* A spot light from above, its full cone (hot angle) inside a wider one
 * that fades linearly to nothing (outer angle). */
static TQ3GroupObject lights_spot(void)
{
    TQ3GroupObject group = Q3LightGroup_New();
    TQ3SpotLightData data;
    data.lightData = light_data(1.2f, rgb(1, 1, 1));
    data.castsShadows = kQ3False;
    data.attenuation = kQ3AttenuationTypeNone;
    data.location = point3(0.0f, 4.0f, 0.5f);
    data.direction = vector3(0.0f, -1.0f, -0.15f);
    data.hotAngle = 0.22f;
    data.outerAngle = 0.42f;
    data.fallOff = kQ3FallOffTypeLinear;
    return finish(group, group != NULL && add_ambient(group, 0.1f) && add_light(group, Q3SpotLight_New(&data)));
}

/* Softer viewer lights and a point light near the camera, for highlights
 * (together at most 1.2: a white surface facing them all stays unsaturated
 * but for its highlights). */
static TQ3GroupObject lights_highlights(void)
{
    TQ3GroupObject group = Q3LightGroup_New();
    TQ3PointLightData data;
    data.lightData = light_data(0.45f, rgb(1, 1, 1));
    data.castsShadows = kQ3False;
    data.attenuation = kQ3AttenuationTypeNone;
    data.location = point3(-2.0f, 3.0f, 5.0f);
    return finish(group, group != NULL && add_ambient(group, 0.2f) &&
                             add_directional(group, 0.55f, vector3(0.6f, -0.5f, -0.6f)) &&
                             add_light(group, Q3PointLight_New(&data)));
}

/* ---- Scenes --------------------------------------------------------------- */

/* The stage the light scenes share: a grey floor, a red sphere, a blue box
 * and a green torus, lit through a Lambert shader at every pixel (the floor
 * is one polygon: lit at its four corners only, a spot light's pool of
 * light between them would not show). */
static TQ3Status submit_stage(TQ3ViewObject view)
{
    TQ3Status status = kQ3Success;
    TQ3AttributeSet grey = surface_set(rgb(0.8f, 0.8f, 0.8f));
    TQ3AttributeSet red = surface_set(rgb(0.9f, 0.25f, 0.2f));
    TQ3AttributeSet blue = surface_set(rgb(0.25f, 0.4f, 0.9f));
    TQ3AttributeSet green = surface_set(rgb(0.3f, 0.8f, 0.35f));

    if (Q3InterpolationStyle_Submit(kQ3InterpolationStylePixel, view) != kQ3Success ||
        submit_new(Q3LambertIllumination_New(), view) != kQ3Success ||
        submit_new(new_floor(-1.0f, 3.0f, grey), view) != kQ3Success ||
        submit_new(new_sphere(point3(-1.3f, -0.2f, 0.0f), 0.8f, red), view) != kQ3Success ||
        submit_new(new_box(point3(0.2f, -1.0f, -0.8f), 1.1f, blue), view) != kQ3Success ||
        submit_new(new_torus(point3(1.2f, -0.75f, 1.0f), 0.55f, 0.25f, 0, green), view) != kQ3Success)
        status = kQ3Failure;
    dispose(grey);
    dispose(red);
    dispose(blue);
    dispose(green);
    return status;
}

/* A white sphere and an orange torus under the shader given, lit at every
 * pixel (highlights are smaller than the triangles). */
static TQ3Status submit_shaded(TQ3ViewObject view, TQ3ShaderObject shader)
{
    TQ3Status status = kQ3Success;
    TQ3AttributeSet white = surface_set(rgb(0.85f, 0.85f, 0.85f));
    TQ3AttributeSet orange = surface_set(rgb(0.95f, 0.5f, 0.15f));
    if (Q3InterpolationStyle_Submit(kQ3InterpolationStylePixel, view) != kQ3Success ||
        submit_new(shader, view) != kQ3Success ||
        submit_new(new_sphere(point3(-1.0f, 0.0f, 0.0f), 1.0f, white), view) != kQ3Success ||
        submit_new(new_torus(point3(1.3f, 0.0f, 0.0f), 0.7f, 0.3f, 1, orange), view) != kQ3Success)
        status = kQ3Failure;
    dispose(white);
    dispose(orange);
    return status;
}

static TQ3Status submit_null_illumination(TQ3ViewObject view)
{
    return submit_shaded(view, Q3NULLIllumination_New());
}

static TQ3Status submit_lambert_illumination(TQ3ViewObject view)
{
    return submit_shaded(view, Q3LambertIllumination_New());
}

static TQ3Status submit_phong_illumination(TQ3ViewObject view)
{
    return submit_shaded(view, Q3PhongIllumination_New());
}

/* A torus and a box, Lambert-lit, in the fill style given. */
static TQ3Status submit_filled(TQ3ViewObject view, TQ3FillStyle fill)
{
    TQ3Status status = kQ3Success;
    TQ3AttributeSet teal = surface_set(rgb(0.2f, 0.75f, 0.75f));
    TQ3AttributeSet yellow = surface_set(rgb(0.95f, 0.85f, 0.2f));
    TQ3SubdivisionStyleData coarse;
    coarse.method = kQ3SubdivisionMethodConstant;
    coarse.c1 = 24.0f;
    coarse.c2 = 12.0f;
    if (Q3FillStyle_Submit(fill, view) != kQ3Success || Q3SubdivisionStyle_Submit(&coarse, view) != kQ3Success ||
        submit_new(Q3LambertIllumination_New(), view) != kQ3Success ||
        submit_new(new_torus(point3(-0.9f, 0.0f, 0.0f), 0.8f, 0.35f, 0, teal), view) != kQ3Success ||
        submit_new(new_box(point3(0.6f, -0.6f, -0.6f), 1.2f, yellow), view) != kQ3Success)
        status = kQ3Failure;
    dispose(teal);
    dispose(yellow);
    return status;
}

static TQ3Status submit_fill_filled(TQ3ViewObject view)
{
    return submit_filled(view, kQ3FillStyleFilled);
}

static TQ3Status submit_fill_edges(TQ3ViewObject view)
{
    return submit_filled(view, kQ3FillStyleEdges);
}

static TQ3Status submit_fill_points(TQ3ViewObject view)
{
    return submit_filled(view, kQ3FillStylePoints);
}

/* The far half of an open cylinder (no caps), seen from above the open side,
 * so that the inside faces the camera: those are back faces. */
static TQ3Status submit_backfacing(TQ3ViewObject view, TQ3BackfacingStyle backfacing)
{
    TQ3CylinderData data;
    TQ3Status status = kQ3Success;
    TQ3AttributeSet violet = surface_set(rgb(0.7f, 0.4f, 0.9f));
    memset(&data, 0, sizeof data);
    data.origin = point3(0.0f, -1.0f, 0.0f);
    data.orientation = vector3(0.0f, 2.0f, 0.0f);
    data.majorRadius = vector3(0.0f, 0.0f, 1.4f);
    data.minorRadius = vector3(1.4f, 0.0f, 0.0f);
    data.uMin = 0.0f;
    data.uMax = 0.75f;
    data.vMax = 1.0f;
    data.cylinderAttributeSet = violet;
    if (Q3BackfacingStyle_Submit(backfacing, view) != kQ3Success ||
        submit_new(Q3LambertIllumination_New(), view) != kQ3Success ||
        submit_new(Q3Cylinder_New(&data), view) != kQ3Success)
        status = kQ3Failure;
    dispose(violet);
    return status;
}

static TQ3Status submit_backfacing_both(TQ3ViewObject view)
{
    return submit_backfacing(view, kQ3BackfacingStyleBoth);
}

static TQ3Status submit_backfacing_remove(TQ3ViewObject view)
{
    return submit_backfacing(view, kQ3BackfacingStyleRemove);
}

static TQ3Status submit_backfacing_flip(TQ3ViewObject view)
{
    return submit_backfacing(view, kQ3BackfacingStyleFlip);
}

/* A coarse Phong-lit sphere (12 x 8 segments) in the interpolation style
 * given: one colour per triangle, colours blended from the vertices, or
 * lit at every pixel. */
static TQ3Status submit_interpolated(TQ3ViewObject view, TQ3InterpolationStyle interpolation)
{
    TQ3Status status = kQ3Success;
    TQ3AttributeSet white = surface_set(rgb(0.75f, 0.75f, 0.8f));
    TQ3SubdivisionStyleData coarse;
    coarse.method = kQ3SubdivisionMethodConstant;
    coarse.c1 = 12.0f;
    coarse.c2 = 8.0f;
    if (Q3InterpolationStyle_Submit(interpolation, view) != kQ3Success ||
        Q3SubdivisionStyle_Submit(&coarse, view) != kQ3Success ||
        submit_new(Q3PhongIllumination_New(), view) != kQ3Success ||
        submit_new(new_sphere(point3(0.0f, 0.0f, 0.0f), 1.5f, white), view) != kQ3Success)
        status = kQ3Failure;
    dispose(white);
    return status;
}

static TQ3Status submit_interpolation_none(TQ3ViewObject view)
{
    return submit_interpolated(view, kQ3InterpolationStyleNone);
}

static TQ3Status submit_interpolation_vertex(TQ3ViewObject view)
{
    return submit_interpolated(view, kQ3InterpolationStyleVertex);
}

static TQ3Status submit_interpolation_pixel(TQ3ViewObject view)
{
    return submit_interpolated(view, kQ3InterpolationStylePixel);
}

/* One group, in the order added: a box, a move to the right, a red colour,
 * a sphere. Unordered, the move and the colour apply to the sphere only;
 * ordered (transforms, then attribute sets, then geometries), to both. */
static TQ3Status submit_group(TQ3ViewObject view, TQ3GroupObject group)
{
    TQ3Status status = kQ3Success;
    TQ3Vector3D right = vector3(1.6f, 0.0f, 0.0f);
    TQ3TransformObject move = Q3TranslateTransform_New(&right);
    TQ3AttributeSet red = surface_set(rgb(0.9f, 0.2f, 0.2f));
    TQ3GeometryObject box = new_box(point3(-1.9f, -0.6f, -0.6f), 1.2f, NULL);
    TQ3GeometryObject sphere = new_sphere(point3(-1.3f, 0.0f, 1.2f), 0.7f, NULL);
    if (group == NULL || move == NULL || red == NULL || box == NULL || sphere == NULL ||
        Q3Group_AddObject(group, box) == NULL || Q3Group_AddObject(group, move) == NULL ||
        Q3Group_AddObject(group, red) == NULL || Q3Group_AddObject(group, sphere) == NULL ||
        submit_new(Q3LambertIllumination_New(), view) != kQ3Success || Q3Object_Submit(group, view) != kQ3Success)
        status = kQ3Failure;
    dispose(group);
    dispose(move);
    dispose(red);
    dispose(box);
    dispose(sphere);
    return status;
}

static TQ3Status submit_group_unordered(TQ3ViewObject view)
{
    return submit_group(view, Q3DisplayGroup_New());
}

static TQ3Status submit_group_ordered(TQ3ViewObject view)
{
    return submit_group(view, Q3OrderedDisplayGroup_New());
}

/* The NURB patches of samples/scenes, Phong-lit, with 16-pixel subdivision. */
static TQ3Status submit_lit_patch(TQ3ViewObject view, TQ3Status (*submit)(TQ3ViewObject, TQ3AttributeSet, float),
                                  TQ3ColorRGB color)
{
    TQ3AttributeSet set = surface_set(color);
    TQ3Status status = kQ3Failure;
    if (set != NULL && submit_new(Q3PhongIllumination_New(), view) == kQ3Success)
        status = submit(view, set, 16.0f);
    dispose(set);
    return status;
}

static TQ3Status submit_patch_plain(TQ3ViewObject view)
{
    return submit_lit_patch(view, q3scene_submit_plain_patch, rgb(0.95f, 0.7f, 0.25f));
}

static TQ3Status submit_patch_trimmed(TQ3ViewObject view)
{
    return submit_lit_patch(view, q3scene_submit_trimmed_patch, rgb(0.35f, 0.8f, 0.4f));
}

static TQ3Status submit_patch_cylinder(TQ3ViewObject view)
{
    return submit_lit_patch(view, q3scene_submit_cylinder_patch, rgb(0.4f, 0.6f, 0.95f));
}

#define INTERACTIVE kQ3RendererTypeInteractive
#define DARK {0.1f, 0.1f, 0.13f}

static const Q3LitScene kLitScenes[] = {
    {{"light_ambient", "The stage lit by an ambient light only: flat colours, no shape", INTERACTIVE,
      {0.0f, 2.2f, 6.0f}, 0.75f, DARK, submit_stage},
     lights_ambient},
    {{"light_directional", "The stage lit by a directional light from the upper left and a dim ambient light",
      INTERACTIVE, {0.0f, 2.2f, 6.0f}, 0.75f, DARK, submit_stage},
     lights_directional},
    {{"light_point", "The stage lit by a warm point light above its front left, fading with distance (1/d)",
      INTERACTIVE, {0.0f, 2.2f, 6.0f}, 0.75f, DARK, submit_stage},
     lights_point},
    {{"light_spot", "The stage under a spot light from above: a full cone fading linearly to its outer angle",
      INTERACTIVE, {0.0f, 2.2f, 6.0f}, 0.75f, DARK, submit_stage},
     lights_spot},
    {{"illumination_null", "NULL illumination: the sphere and torus in their diffuse colours, unlit", INTERACTIVE,
      {0.0f, 1.0f, 6.0f}, 0.7f, DARK, submit_null_illumination},
     lights_highlights},
    {{"illumination_lambert", "Lambert illumination: ambient and diffuse light, no highlights", INTERACTIVE,
      {0.0f, 1.0f, 6.0f}, 0.7f, DARK, submit_lambert_illumination},
     lights_highlights},
    {{"illumination_phong", "Phong illumination: Lambert plus white highlights (specular control 15)",
      INTERACTIVE, {0.0f, 1.0f, 6.0f}, 0.7f, DARK, submit_phong_illumination},
     lights_highlights},
    {{"fill_filled", "Fill style filled: a torus and a box, lit", INTERACTIVE, {0.5f, 2.0f, 5.0f}, 0.7f, DARK,
      submit_fill_filled},
     lights_viewer},
    {{"fill_edges", "Fill style edges: the same triangles' edges, lit", INTERACTIVE, {0.5f, 2.0f, 5.0f}, 0.7f, DARK,
      submit_fill_edges},
     lights_viewer},
    {{"fill_points", "Fill style points: the same triangles' vertices, lit", INTERACTIVE, {0.5f, 2.0f, 5.0f}, 0.7f,
      DARK, submit_fill_points},
     lights_viewer},
    {{"backfacing_both", "Backfacing both: the open cylinder's inside drawn, lit as its outside would be",
      INTERACTIVE, {0.0f, 3.0f, 4.5f}, 0.75f, DARK, submit_backfacing_both},
     lights_viewer},
    {{"backfacing_remove", "Backfacing remove: the open cylinder's inside not drawn", INTERACTIVE,
      {0.0f, 3.0f, 4.5f}, 0.75f, DARK, submit_backfacing_remove},
     lights_viewer},
    {{"backfacing_flip", "Backfacing flip: the inside drawn and lit with its normals reversed", INTERACTIVE,
      {0.0f, 3.0f, 4.5f}, 0.75f, DARK, submit_backfacing_flip},
     lights_viewer},
    {{"interpolation_none", "Interpolation none: a coarse Phong-lit sphere, one colour per triangle", INTERACTIVE,
      {0.0f, 0.0f, 5.0f}, 0.75f, DARK, submit_interpolation_none},
     lights_highlights},
    {{"interpolation_vertex", "Interpolation vertex: the same sphere, colours blended from its vertices",
      INTERACTIVE, {0.0f, 0.0f, 5.0f}, 0.75f, DARK, submit_interpolation_vertex},
     lights_highlights},
    {{"interpolation_pixel", "Interpolation pixel: the same sphere lit at every pixel", INTERACTIVE,
      {0.0f, 0.0f, 5.0f}, 0.75f, DARK, submit_interpolation_pixel},
     lights_highlights},
    {{"group_unordered", "Display group [box, move right, red, sphere]: the move and the colour reach the sphere only",
      INTERACTIVE, {0.0f, 2.0f, 6.0f}, 0.7f, DARK, submit_group_unordered},
     lights_viewer},
    {{"group_ordered", "Ordered display group, same objects: the move and the colour come first and reach both",
      INTERACTIVE, {0.0f, 2.0f, 6.0f}, 0.7f, DARK, submit_group_ordered},
     lights_viewer},
    {{"patch_plain", "A bicubic NURB patch, Phong-lit: normals from the exact derivatives", INTERACTIVE,
      {0.0f, 3.8f, 5.4f}, 0.75f, DARK, submit_patch_plain},
     lights_highlights},
    {{"patch_trimmed", "The patch trimmed: a circular hole with a square island in it, lit", INTERACTIVE,
      {0.0f, 3.8f, 5.4f}, 0.75f, DARK, submit_patch_trimmed},
     lights_highlights},
    {{"patch_cylinder", "A rational patch that is exactly half a cylinder, lit", INTERACTIVE,
      {4.2f, 3.0f, 1.8f}, 0.75f, DARK, submit_patch_cylinder},
     lights_highlights},
};

unsigned long q3litscene_count(void)
{
    return sizeof kLitScenes / sizeof kLitScenes[0];
}

const Q3LitScene *q3litscene_get(unsigned long index)
{
    return index < q3litscene_count() ? &kLitScenes[index] : NULL;
}

const Q3LitScene *q3litscene_find(const char *name)
{
    unsigned long i;
    if (name == NULL)
        return NULL;
    for (i = 0; i < q3litscene_count(); i++)
        if (strcmp(kLitScenes[i].scene.name, name) == 0)
            return &kLitScenes[i];
    return NULL;
}

int q3litscene_render(const Q3LitScene *scene, unsigned long width, unsigned long height, unsigned char *rgba)
{
    TQ3GroupObject lights;
    int result;
    if (scene == NULL)
        return 1;
    lights = scene->lights();
    if (lights == NULL)
        return 1;
    result = q3scene_render_lit(&scene->scene, lights, width, height, rgba);
    Q3Object_Dispose(lights);
    return result;
}
