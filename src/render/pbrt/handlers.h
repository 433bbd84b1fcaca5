#pragma once
// The handlers of the directive table (directives.cpp), each group in a file of its own.

#include "render/pbrt/directives.h"

namespace lenslab::render::pbrt {

// directives_transform.cpp: the current transformation matrix.
bool translate(const DirectiveCall& call);
bool scale(const DirectiveCall& call);
bool rotate(const DirectiveCall& call);
bool lookAt(const DirectiveCall& call);
bool transform(const DirectiveCall& call);  // Transform and ConcatTransform
bool identity(const DirectiveCall& call);
bool coordinateSystem(const DirectiveCall& call);
bool coordSysTransform(const DirectiveCall& call);
bool motionBlurTransform(const DirectiveCall& call);  // TransformTimes, ActiveTransform

// directives_blocks.cpp: attribute, transform, world and object blocks, object instances.
bool attributeOrTransformBegin(const DirectiveCall& call);
bool attributeOrTransformEnd(const DirectiveCall& call);
bool worldBegin(const DirectiveCall& call);
bool worldEnd(const DirectiveCall& call);
bool objectBegin(const DirectiveCall& call);
bool objectEnd(const DirectiveCall& call);
bool objectInstance(const DirectiveCall& call);

// directives_camera.cpp
bool camera(const DirectiveCall& call);

// directives_options.cpp: film, sampler, filter, integrator, and options lenslab ignores.
bool film(const DirectiveCall& call);
bool sampler(const DirectiveCall& call);
bool pixelFilter(const DirectiveCall& call);
bool integrator(const DirectiveCall& call);  // Integrator and pbrt-v2's SurfaceIntegrator
bool unsupportedWithParams(const DirectiveCall& call);  // VolumeIntegrator, ColorSpace, ...
bool mediumInterface(const DirectiveCall& call);

// directives_materials.cpp
bool material(const DirectiveCall& call);
bool makeNamedMaterial(const DirectiveCall& call);
bool namedMaterial(const DirectiveCall& call);
bool texture(const DirectiveCall& call);

// directives_lights.cpp
bool lightSource(const DirectiveCall& call);
bool areaLightSource(const DirectiveCall& call);

// directives_shapes.cpp
bool shape(const DirectiveCall& call);
bool reverseOrientation(const DirectiveCall& call);

}  // namespace lenslab::render::pbrt
