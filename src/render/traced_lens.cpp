#include "render/traced_lens.h"

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <sstream>

namespace lenslab::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Vector form of Snell's law; `normal` faces the incoming ray. eta = etaIncident / etaOutgoing.
std::optional<glm::dvec3> refract(glm::dvec3 direction, glm::dvec3 normal, double eta) {
  const double cosI = -glm::dot(direction, normal);
  const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
  if (sin2T > 1.0) return std::nullopt;  // total internal reflection
  const double cosT = std::sqrt(1.0 - sin2T);
  return eta * direction + (eta * cosI - cosT) * normal;
}

// Concentric map of the unit square onto the unit disk (Shirley and Chiu 1997).
glm::dvec2 concentric(glm::dvec2 u) {
  const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
  if (a == 0.0 && b == 0.0) return {0.0, 0.0};
  double r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = (kPi / 4.0) * (b / a);
  } else {
    r = b;
    phi = kPi / 2.0 - (kPi / 4.0) * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace

std::optional<std::vector<TracedLens::Row>> TracedLens::readFile(
    const std::filesystem::path& path, std::string& error) {
  std::ifstream input(path);
  if (!input) {
    error = "cannot open lens file " + path.string();
    return std::nullopt;
  }
  std::vector<Row> rows;
  std::string line;
  int lineNumber = 0;
  while (std::getline(input, line)) {
    ++lineNumber;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::vector<double> values;
    double value;
    while (words >> value) values.push_back(value);
    if (values.empty()) continue;
    if (values.size() != 4) {
      error = path.string() + ":" + std::to_string(lineNumber) +
              ": expected 4 numbers (radius thickness index aperture), found " +
              std::to_string(values.size());
      return std::nullopt;
    }
    rows.push_back({values[0], values[1], values[2], values[3]});
  }
  if (rows.empty()) {
    error = path.string() + ": no lens surfaces";
    return std::nullopt;
  }
  return rows;
}

TracedLens::TracedLens(const std::vector<Row>& rows, double filmDistanceMm,
                       double stopDiameterMm) {
  // Place the rear vertex at the film distance and walk to the front.
  double z = filmDistanceMm;
  for (std::size_t i = rows.size(); i-- > 0;) {
    if (i + 1 < rows.size()) z += rows[i].thicknessMm;
    LensInterface surface;
    surface.radiusMm = rows[i].radiusMm;
    surface.zMm = z;
    surface.apertureRadiusMm = 0.5 * rows[i].apertureDiameterMm;
    if (rows[i].radiusMm == 0.0 && stopDiameterMm > 0.0) {
      surface.apertureRadiusMm = std::min(surface.apertureRadiusMm, 0.5 * stopDiameterMm);
    }
    surface.indexFilmSide = rows[i].index == 0.0 ? 1.0 : rows[i].index;
    interfaces_.push_back(surface);
  }
}

std::optional<LensRayMm> TracedLens::traceFromFilm(const LensRayMm& input) const {
  glm::dvec3 origin = input.origin;
  glm::dvec3 direction = glm::normalize(input.direction);
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const LensInterface& surface = interfaces_[i];
    glm::dvec3 hit;
    glm::dvec3 normal;
    if (surface.radiusMm == 0.0) {
      if (direction.z <= 0.0) return std::nullopt;
      const double t = (surface.zMm - origin.z) / direction.z;
      hit = origin + t * direction;
      normal = {0.0, 0.0, -1.0};
    } else {
      // Sphere with its centre on the axis; R > 0 puts the centre toward the film.
      const glm::dvec3 center(0.0, 0.0, surface.zMm - surface.radiusMm);
      const glm::dvec3 oc = origin - center;
      const double b = glm::dot(oc, direction);
      const double c = glm::dot(oc, oc) - surface.radiusMm * surface.radiusMm;
      const double discriminant = b * b - c;
      if (discriminant < 0.0) return std::nullopt;
      const double root = std::sqrt(discriminant);
      // Going toward +z, the vertex is the far side of a sphere whose centre lies behind it.
      const double t = surface.radiusMm > 0.0 ? -b + root : -b - root;
      if (t <= 0.0) return std::nullopt;
      hit = origin + t * direction;
      normal = glm::normalize(hit - center);
      if (glm::dot(normal, direction) > 0.0) normal = -normal;
    }
    if (hit.x * hit.x + hit.y * hit.y > surface.apertureRadiusMm * surface.apertureRadiusMm) {
      return std::nullopt;
    }
    if (surface.radiusMm != 0.0) {
      const double etaIncident = surface.indexFilmSide;
      const double etaOutgoing =
          i + 1 < interfaces_.size() ? interfaces_[i + 1].indexFilmSide : 1.0;
      const auto refracted = refract(direction, normal, etaIncident / etaOutgoing);
      if (!refracted) return std::nullopt;
      direction = glm::normalize(*refracted);
    }
    origin = hit;
  }
  return LensRayMm{origin, direction};
}

std::optional<PupilSampleMm> TracedLens::sampleExitPupil(glm::dvec2, glm::dvec2 u) const {
  const LensInterface& rear = interfaces_.front();
  const glm::dvec2 disk = rear.apertureRadiusMm * concentric(u);
  PupilSampleMm sample;
  sample.pointMm = {disk.x, disk.y, rear.zMm};
  sample.pdfPerMm2 = 1.0 / (kPi * rear.apertureRadiusMm * rear.apertureRadiusMm);
  return sample;
}

std::optional<double> TracedLens::focusFilmDistance(const std::vector<Row>& rows,
                                                    double stopDiameterMm,
                                                    double objectDistanceMm) {
  // Where a ray from the film centre through a point near the axis crosses the axis again.
  auto crossing = [&](double filmDistance) -> std::optional<double> {
    const TracedLens lens(rows, filmDistance, stopDiameterMm);
    const double height = 0.01 * lens.interfaces_.front().apertureRadiusMm;
    const auto out =
        lens.traceFromFilm({{0.0, 0.0, 0.0}, {height, 0.0, lens.rearZMm()}});
    if (!out || out->direction.x >= 0.0) return std::nullopt;  // not converging
    return out->origin.z - out->origin.x / out->direction.x * out->direction.z;
  };
  // Moving the film away from the lens brings the focus closer; bisect on the film distance.
  double lo = 1e-3, hi = 0.0;
  for (const Row& row : rows) hi += std::abs(row.thicknessMm) + std::abs(row.radiusMm);
  hi = std::max(hi, 10.0);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    const auto z = crossing(mid);
    if (!z || *z > objectDistanceMm) {
      lo = mid;  // focus too far (or at infinity): move the film back
    } else {
      hi = mid;
    }
  }
  const auto check = crossing(hi);
  if (!check || std::abs(*check - objectDistanceMm) > 0.01 * objectDistanceMm) return std::nullopt;
  return hi;
}

}  // namespace lenslab::render
