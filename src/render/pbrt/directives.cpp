#include "render/pbrt/directives.h"

#include <algorithm>
#include <iterator>

#include "render/pbrt/handlers.h"

namespace lenslab::render::pbrt {

namespace {

constexpr Placement kAnywhere = Placement::Anywhere;
constexpr Placement kBeforeWorld = Placement::BeforeWorld;

constexpr Directive kDirectives[] = {
    // Transformations
    {"Translate", translate, kAnywhere},
    {"Scale", scale, kAnywhere},
    {"Rotate", rotate, kAnywhere},
    {"LookAt", lookAt, kAnywhere},
    {"Transform", transform, kAnywhere},
    {"ConcatTransform", transform, kAnywhere},
    {"Identity", identity, kAnywhere},
    {"CoordinateSystem", coordinateSystem, kAnywhere},
    {"CoordSysTransform", coordSysTransform, kAnywhere},
    {"TransformTimes", motionBlurTransform, kAnywhere},
    {"ActiveTransform", motionBlurTransform, kAnywhere},
    // Blocks and instances
    {"AttributeBegin", attributeOrTransformBegin, kAnywhere},
    {"TransformBegin", attributeOrTransformBegin, kAnywhere},
    {"AttributeEnd", attributeOrTransformEnd, kAnywhere},
    {"TransformEnd", attributeOrTransformEnd, kAnywhere},
    {"WorldBegin", worldBegin, kAnywhere},
    {"WorldEnd", worldEnd, kAnywhere},
    {"ObjectBegin", objectBegin, kAnywhere},
    {"ObjectEnd", objectEnd, kAnywhere},
    {"ObjectInstance", objectInstance, kAnywhere},
    // Scene-wide options
    {"Camera", camera, kBeforeWorld},
    {"Film", film, kBeforeWorld},
    {"Sampler", sampler, kBeforeWorld},
    {"PixelFilter", pixelFilter, kBeforeWorld},
    {"Integrator", integrator, kBeforeWorld},
    {"SurfaceIntegrator", integrator, kBeforeWorld},
    {"VolumeIntegrator", unsupportedWithParams, kBeforeWorld},
    {"Accelerator", unsupportedWithParams, kBeforeWorld},
    {"Renderer", unsupportedWithParams, kBeforeWorld},
    {"MakeNamedMedium", unsupportedWithParams, kAnywhere},
    {"ColorSpace", unsupportedWithParams, kAnywhere},
    {"Option", unsupportedWithParams, kAnywhere},
    {"MediumInterface", mediumInterface, kAnywhere},
    // Materials and textures
    {"Material", material, kAnywhere},
    {"MakeNamedMaterial", makeNamedMaterial, kAnywhere},
    {"NamedMaterial", namedMaterial, kAnywhere},
    {"Texture", texture, kAnywhere},
    // Lights
    {"LightSource", lightSource, kAnywhere},
    {"AreaLightSource", areaLightSource, kAnywhere},
    // Shapes
    {"Shape", shape, kAnywhere},
    {"ReverseOrientation", reverseOrientation, kAnywhere},
};

}  // namespace

const Directive* findDirective(std::string_view name) {
  const auto found = std::find_if(std::begin(kDirectives), std::end(kDirectives),
                                  [&](const Directive& d) { return d.name == name; });
  return found == std::end(kDirectives) ? nullptr : &*found;
}

}  // namespace lenslab::render::pbrt
