#include "core/sim/frame_packet_codec.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>

#include "core/util/byte_reader.h"
#include "core/util/byte_writer.h"
#include "core/util/half_arrays.h"
#include "core/util/hash.h"

namespace sandstorm {
namespace {

constexpr std::uint32_t kPacketMagic = 0x50465353;  // "SSFP"
constexpr std::uint32_t kFieldMagic = 0x46565353;   // "SSVF"
// 2: equation terms, lod scale; 3: tracking, wand ray; 4: grid validity;
// 5: field range; 6: vorticity; 7: colour grids by name, grids' scalar arrays.
constexpr std::uint16_t kVersion = 12;
constexpr std::uint32_t kMaxScalarArrays = 256;
// Components a half grid is converted by at a time (on the stack: 8 KiB).
constexpr std::size_t kHalfBlock = 4096;

// Limits far above any real packet, so a corrupt count cannot make us allocate gigabytes.
constexpr std::uint32_t kMaxChanges = 4096;
constexpr std::uint32_t kMaxEmission = 4096;
constexpr std::size_t kMaxString = 4096;

enum class ValueTag : std::uint8_t { Bool = 0, Int = 1, Float = 2, Vec3 = 3, Text = 4 };
static_assert(std::is_same_v<std::variant_alternative_t<3, AttributeValue>, glm::vec3> &&
                  std::variant_size_v<AttributeValue> == 5,
              "AttributeValue changed: update ValueTag and value()");

// A member added to a type that travels must travel too: these sizes make the
// build fail until the codec (and its test) learn the new member.
#if defined(__x86_64__) && defined(__linux__)
// (FramePacket::upcomingField stays behind on purpose: a hint for the walls of
// this process; ranks upload each frame as it comes.)
static_assert(sizeof(FramePacket) == 352, "FramePacket changed: update encodePacket/decodePacket");
static_assert(sizeof(StateChange) == 160, "StateChange changed: update change()");
static_assert(sizeof(Emitter) == 72, "Emitter changed: update emitter()");
static_assert(sizeof(Viewer) == 48, "Viewer changed: update encodePacket/decodePacket");
static_assert(sizeof(TrackingSample) == 124, "TrackingSample changed: update tracking()");
static_assert(sizeof(WandRay) == 40, "WandRay changed: update wandRay()");
static_assert(sizeof(FieldPlacement) == 52, "FieldPlacement changed: update placement()");
#endif

void vec3(ByteWriter& w, const glm::vec3& v) {
  w.f32(v.x);
  w.f32(v.y);
  w.f32(v.z);
}

glm::vec3 vec3(ByteReader& r, std::string_view what) {
  glm::vec3 v;
  v.x = r.f32(what);
  v.y = r.f32(what);
  v.z = r.f32(what);
  return v;
}

void value(ByteWriter& w, const AttributeValue& v) {
  w.u8(std::uint8_t(v.index()));
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>)
          w.boolean(x);
        else if constexpr (std::is_same_v<T, int>)
          w.i32(x);
        else if constexpr (std::is_same_v<T, float>)
          w.f32(x);
        else if constexpr (std::is_same_v<T, glm::vec3>)
          vec3(w, x);
        else
          w.str(x);
      },
      v);
}

AttributeValue value(ByteReader& r) {
  const std::uint8_t tag = r.u8("change.value type");
  switch (ValueTag(tag)) {
    case ValueTag::Bool:
      return r.boolean("change.value");
    case ValueTag::Int:
      return int(r.i32("change.value"));
    case ValueTag::Float:
      return r.f32("change.value");
    case ValueTag::Vec3:
      return vec3(r, "change.value");
    case ValueTag::Text:
      return r.str("change.value", kMaxString);
  }
  r.fail("change.value type",
         concat("expected 0..4 (bool, int, float, vec3, text), got ", int(tag)));
}

void emitter(ByteWriter& w, const Emitter& e) {
  w.i32(int(e.shape));
  vec3(w, e.position);
  w.f32(e.width);
  w.f32(e.depth);
  w.f32(e.height);
  w.f32(e.radius);
  w.f32(e.rate);
  w.f32(e.rateVariance);
  w.f32(e.lifetime);
  w.f32(e.lifetimeVariance);
  vec3(w, e.velocity);
  w.f32(e.spread);
  w.boolean(e.enabled);
  w.i32(int(e.kind));
}

Emitter emitter(ByteReader& r) {
  Emitter e;
  const std::int32_t shape = r.i32("change.emitter.shape");
  if (shape < 0 || shape > int(EmitterShape::Point))
    r.fail("change.emitter.shape", concat("expected 0..3 (box, sphere, disc, point), got ", shape));
  e.shape = EmitterShape(shape);
  e.position = vec3(r, "change.emitter.position");
  e.width = r.f32("change.emitter.width");
  e.depth = r.f32("change.emitter.depth");
  e.height = r.f32("change.emitter.height");
  e.radius = r.f32("change.emitter.radius");
  e.rate = r.f32("change.emitter.rate");
  e.rateVariance = r.f32("change.emitter.rate_variance");
  e.lifetime = r.f32("change.emitter.lifetime");
  e.lifetimeVariance = r.f32("change.emitter.lifetime_variance");
  e.velocity = vec3(r, "change.emitter.velocity");
  e.spread = r.f32("change.emitter.spread");
  e.enabled = r.boolean("change.emitter.enabled");
  const std::int32_t kind = r.i32("change.emitter.kind");
  if (kind < 0 || kind > int(EmitterKind::Molecules))
    r.fail("change.emitter.kind", concat("expected 0..1 (particles, molecules), got ", kind));
  e.kind = EmitterKind(kind);
  return e;
}

// Every member of a change travels, whatever its kind, so a round trip is exact.
void change(ByteWriter& w, const StateChange& c) {
  w.u8(std::uint8_t(c.kind));
  w.str(c.key);
  value(w, c.value);
  w.i32(c.index);
  emitter(w, c.emitter);
}

StateChange change(ByteReader& r) {
  StateChange c;
  const std::uint8_t kind = r.u8("change.kind");
  if (kind > std::uint8_t(StateChange::Kind::Reset))
    r.fail("change.kind",
           concat("expected 0..3 (set, add-emitter, remove-emitter, reset), got ", int(kind)));
  c.kind = StateChange::Kind(kind);
  c.key = r.str("change.key", kMaxString);
  c.value = value(r);
  c.index = r.i32("change.index");
  c.emitter = emitter(r);
  return c;
}

void placement(ByteWriter& w, const FieldPlacement& p) {
  vec3(w, p.offset);
  w.f32(p.scale);
  for (int c = 0; c < 3; ++c)
    vec3(w, p.rotation[c]);
}

FieldPlacement placement(ByteReader& r) {
  FieldPlacement p;
  p.offset = vec3(r, "field.placement.offset");
  p.scale = r.f32("field.placement.scale");
  for (int c = 0; c < 3; ++c)
    p.rotation[c] = vec3(r, "field.placement.rotation");
  return p;
}

void pose(ByteWriter& w, const TrackedPose& p) {
  vec3(w, p.position);
  for (int c = 0; c < 3; ++c)
    vec3(w, p.axes[c]);
}

TrackedPose pose(ByteReader& r, std::string_view what) {
  TrackedPose p;
  p.position = vec3(r, what);
  for (int c = 0; c < 3; ++c)
    p.axes[c] = vec3(r, what);
  return p;
}

void tracking(ByteWriter& w, const TrackingSample& s) {
  w.boolean(s.active);
  w.boolean(s.stale);
  w.u32(s.trackerFrame);
  w.boolean(s.headTracked);
  pose(w, s.head);
  w.boolean(s.wand.present);
  w.boolean(s.wand.tracked);
  pose(w, s.wand.pose);
  w.u32(s.wand.buttons);
  w.f32(s.wand.joystick.x);
  w.f32(s.wand.joystick.y);
}

TrackingSample tracking(ByteReader& r) {
  TrackingSample s;
  s.active = r.boolean("tracking.active");
  s.stale = r.boolean("tracking.stale");
  s.trackerFrame = r.u32("tracking.tracker_frame");
  s.headTracked = r.boolean("tracking.head_tracked");
  s.head = pose(r, "tracking.head");
  s.wand.present = r.boolean("tracking.wand.present");
  s.wand.tracked = r.boolean("tracking.wand.tracked");
  s.wand.pose = pose(r, "tracking.wand.pose");
  s.wand.buttons = r.u32("tracking.wand.buttons");
  s.wand.joystick.x = r.f32("tracking.wand.joystick");
  s.wand.joystick.y = r.f32("tracking.wand.joystick");
  return s;
}

void wandRay(ByteWriter& w, const WandRay& ray) {
  w.boolean(ray.visible);
  vec3(w, ray.origin);
  vec3(w, ray.end);
  w.u8(std::uint8_t(ray.target));
  w.i32(ray.emitter);
  w.boolean(ray.holding);
}

WandRay wandRay(ByteReader& r) {
  WandRay ray;
  ray.visible = r.boolean("wand.visible");
  ray.origin = vec3(r, "wand.origin");
  ray.end = vec3(r, "wand.end");
  const std::uint8_t target = r.u8("wand.target");
  if (target > std::uint8_t(WandTarget::Ground))
    r.fail("wand.target", concat("expected 0..3 (none, menu, emitter, ground), got ", int(target)));
  ray.target = WandTarget(target);
  ray.emitter = r.i32("wand.emitter");
  if (ray.emitter < -1 || ray.emitter >= ParticleState::kMaxEmitters)
    r.fail("wand.emitter",
           concat("expected -1..", ParticleState::kMaxEmitters - 1, ", got ", ray.emitter));
  ray.holding = r.boolean("wand.holding");
  return ray;
}

void header(ByteReader& r, std::uint32_t magic, const char* what) {
  const std::uint32_t m = r.u32("magic");
  if (m != magic)
    r.fail("magic", concat("not a ", what, " (magic ", std::hex, m, ", expected ", magic, ")"));
  const std::uint16_t version = r.u16("version");
  if (version != kVersion) r.fail("version", concat("version ", version, ", expected ", kVersion));
}

}  // namespace

std::uint64_t fieldHash(const VectorField& grid) {
  return fnv1a64(encodeField(grid));
}

std::uint64_t sparseHash(const SparseField& grid) {
  return fnv1a64(std::as_bytes(grid.words()));
}

std::vector<std::byte> encodeField(const VectorField& grid) {
  ByteWriter w;
  w.u32(kFieldMagic);
  w.u16(kVersion);
  vec3(w, grid.bounds().min);
  vec3(w, grid.bounds().max);
  for (int a = 0; a < 3; ++a)
    w.i32(grid.dims()[a]);
  const std::span<const glm::vec3> values = grid.values();
  // A half-precision grid travels as its 16-bit floats: half the bytes, exactly.
  w.boolean(grid.halfPrecision());
  if (grid.halfPrecision()) {
    // Converted a block at a time (core/util/half_arrays.h), not one by one.
    const float* components = &values.data()->x;
    std::array<std::uint16_t, kHalfBlock> bits;
    for (std::size_t i = 0; i < 3 * values.size(); i += kHalfBlock) {
      const std::size_t n = std::min(kHalfBlock, 3 * values.size() - i);
      halvesToBits(components + i, n, bits.data());
      w.u16s(std::span<const std::uint16_t>(bits.data(), n));
    }
  } else {
    w.f32s(std::span<const float>(&values.data()->x, values.size() * 3));
  }
  w.boolean(grid.hasValidity());
  if (grid.hasValidity()) w.raw(std::as_bytes(grid.validity()));
  w.u32(std::uint32_t(grid.scalars().size()));
  for (const VectorField::Scalars& a : grid.scalars()) {
    w.str(a.name);
    w.f32s(a.values);
  }
  return w.take();
}

VectorField decodeField(std::span<const std::byte> bytes, std::string_view name) {
  ByteReader r(bytes, std::string(name));
  header(r, kFieldMagic, "field grid");
  Box bounds;
  bounds.min = vec3(r, "bounds_min");
  bounds.max = vec3(r, "bounds_max");
  glm::ivec3 dims;
  for (int a = 0; a < 3; ++a)
    dims[a] = r.i32("dims");
  std::uint64_t points = 1;
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 1)
      r.fail("dims", concat("expected positive dims, got ", dims.x, "x", dims.y, "x", dims.z));
    points *= std::uint64_t(dims[a]);  // at most 2^31 x 2^31 each step: no wrap below the check
    if (points > VectorField::kMaxPoints)
      r.fail("dims", concat(dims.x, "x", dims.y, "x", dims.z, " points exceed the limit of ",
                            VectorField::kMaxPoints));
  }
  // Whether the vectors are halves, the vectors, a flag, the validity mask
  // when the flag says there is one, and the scalar arrays (a count, then a
  // name and a float per point each).
  const bool half = r.boolean("half precision");
  const std::uint64_t vectorBytes = points * (half ? 6 : 12);
  if (r.remaining() < vectorBytes + 5)
    r.fail("values", concat("expected at least ", vectorBytes + 5, " bytes of vectors for ", dims.x,
                            "x", dims.y, "x", dims.z, ", got ", r.remaining()));
  std::vector<glm::vec3> values(points);
  if (half) {
    float* components = &values.data()->x;
    std::array<std::uint16_t, kHalfBlock> bits;
    for (std::size_t i = 0; i < 3 * values.size(); i += kHalfBlock) {
      const std::size_t n = std::min(kHalfBlock, 3 * values.size() - i);
      r.u16s(std::span<std::uint16_t>(bits.data(), n), "values");
      for (std::size_t k = 0; k < n; ++k)
        if ((bits[k] & 0x7c00u) == 0x7c00u)  // the largest exponent: infinity or NaN
          r.fail("values",
                 concat("component ", i + k, ": a half-precision vector that is not finite"));
      bitsToFloats(bits.data(), n, components + i);
    }
  } else {
    r.f32s(std::span<float>(&values.data()->x, values.size() * 3), "values");
  }
  std::vector<std::uint8_t> valid;
  if (r.boolean("validity mask")) {
    const std::span<const std::byte> mask = r.raw(points, "validity mask");
    valid.resize(points);
    for (std::size_t i = 0; i < points; ++i) {
      valid[i] = std::to_integer<std::uint8_t>(mask[i]);
      if (valid[i] > 1) r.fail("validity mask", concat("point ", i, ": expected 0 or 1"));
    }
  }
  const std::uint32_t arrays = r.u32("scalar array count");
  if (arrays > kMaxScalarArrays)
    r.fail("scalar array count", concat(arrays, " exceeds the limit of ", kMaxScalarArrays));
  std::vector<VectorField::Scalars> scalars;
  for (std::uint32_t a = 0; a < arrays; ++a) {
    VectorField::Scalars array{r.str("scalar array name", kMaxString), {}};
    if (r.remaining() < points * 4)
      r.fail("scalar array values", concat("array '", array.name, "': expected ", points * 4,
                                           " bytes, got ", r.remaining()));
    array.values.resize(points);
    r.f32s(array.values, "scalar array values");
    scalars.push_back(std::move(array));
  }
  r.finish();
  try {
    VectorField field(bounds, dims, std::move(values));
    if (half) field.markRoundedToHalf();  // halves by construction, each finite
    field.setValidity(std::move(valid));
    for (VectorField::Scalars& a : scalars)
      field.addScalars(std::move(a.name), std::move(a.values));
    return field;
  } catch (const Error& e) {
    throw Error(concat(name, ": ", e.what()));
  }
}

std::vector<std::byte> encodePacket(const FramePacket& p, const FieldRefs& refs) {
  ByteWriter w;
  w.u32(kPacketMagic);
  w.u16(kVersion);
  w.u32(p.frame);
  w.f32(p.dt);
  w.f32(p.simDt);
  w.f64(p.time);
  w.f64(p.simTime);
  w.u64(p.seed);
  w.boolean(p.reset);
  w.u32(std::uint32_t(p.changes.size()));
  for (const StateChange& c : p.changes)
    change(w, c);
  w.u32(std::uint32_t(p.emission.size()));
  for (const std::uint32_t n : p.emission)
    w.u32(n);
  w.boolean(p.fieldUpdate != nullptr);
  if (p.fieldUpdate) {
    w.u64(refs.field);
    w.u64(refs.next);
    w.u64(refs.sparse);
    placement(w, p.fieldUpdate->placement);
    const FieldRange& range = p.fieldUpdate->range;
    w.f32(range.minSpeed);
    w.f32(range.maxSpeed);
    vec3(w, range.minVelocity);
    vec3(w, range.maxVelocity);
    w.f32(range.minScalar);
    w.f32(range.maxScalar);
    // The colour grid travels by name: the receiver makes it again from the
    // grids (makeColorGrid is deterministic) rather than receiving it.
    std::optional<std::string> colorGrid = refs.colorGrid;
    if (p.fieldUpdate->colorGrid) colorGrid = p.fieldUpdate->colorArray;
    w.boolean(colorGrid.has_value());
    if (colorGrid) w.str(*colorGrid);
    // An analytic field's equation (field.mode = equation) travels whole: it is small.
    const FieldEquation* e = p.fieldUpdate->equation.get();
    w.u32(e ? std::uint32_t(e->terms.size()) : 0u);
    if (e)
      for (const EquationTerm& t : e->terms) {
        w.i32(int(t.kind));
        w.u32(t.seed);
        for (const glm::vec4& v : {t.a, t.b, t.c})
          for (int c = 0; c < 4; ++c)
            w.f32(v[c]);
      }
    // A streamed series' pair by step and file, for ranks that read the steps themselves.
    const std::optional<FieldSeriesRef>& series = p.fieldUpdate->series;
    w.boolean(series.has_value());
    if (series) {
      w.u32(series->steps);
      w.u32(series->first);
      w.u32(series->second);
      for (const FileIdentity& f : {series->firstFile, series->secondFile}) {
        w.boolean(f.present);
        w.u64(f.size);
        w.u64(std::uint64_t(f.modified));
      }
      w.boolean(series->backwards);
      w.boolean(series->loop);
    }
  }
  vec3(w, p.viewer.head.position);
  vec3(w, p.viewer.head.right);
  w.f32(p.viewer.head.eyeSeparation);
  vec3(w, p.viewer.navigation.offset);
  w.f32(p.viewer.navigation.yawRadians);
  w.f32(p.viewer.navigation.scale);
  w.f32(p.fieldBlend);
  w.f32(p.lodScale);
  // Tracking and the wand's ray travel only when there are any (most runs have no tracker).
  w.boolean(p.tracking != TrackingSample{});
  if (p.tracking != TrackingSample{}) tracking(w, p.tracking);
  w.boolean(p.wand != WandRay{});
  if (p.wand != WandRay{}) wandRay(w, p.wand);
  return w.take();
}

FramePacket decodePacket(std::span<const std::byte> bytes, FieldRefs* refs) {
  ByteReader r(bytes, "frame packet");
  header(r, kPacketMagic, "frame packet");
  FramePacket p;
  p.frame = r.u32("frame");
  p.dt = r.f32("dt");
  p.simDt = r.f32("sim_dt");
  p.time = r.f64("time");
  p.simTime = r.f64("sim time");
  p.seed = r.u64("seed");
  p.reset = r.boolean("reset");
  const std::uint32_t changes = r.u32("change count");
  if (changes > kMaxChanges)
    r.fail("change count", concat(changes, " exceeds the limit of ", kMaxChanges));
  for (std::uint32_t i = 0; i < changes; ++i)
    p.changes.push_back(change(r));
  const std::uint32_t emission = r.u32("emission count");
  if (emission > kMaxEmission)
    r.fail("emission count", concat(emission, " exceeds the limit of ", kMaxEmission));
  for (std::uint32_t i = 0; i < emission; ++i)
    p.emission.push_back(r.u32("emission"));
  FieldRefs found;
  if (r.boolean("field update")) {
    found.field = r.u64("field hash");
    found.next = r.u64("next field hash");
    found.sparse = r.u64("sparse field hash");
    FieldUpdate update{.placement = placement(r)};
    update.range.minSpeed = r.f32("field range min speed");
    update.range.maxSpeed = r.f32("field range max speed");
    update.range.minVelocity = vec3(r, "field range min velocity");
    update.range.maxVelocity = vec3(r, "field range max velocity");
    update.range.minScalar = r.f32("field range min scalar");
    update.range.maxScalar = r.f32("field range max scalar");
    if (r.boolean("field colour grid")) found.colorGrid = r.str("field colour grid", kMaxString);
    const std::uint32_t terms = r.u32("equation term count");
    if (terms > std::uint32_t(FieldEquation::kMaxTerms))
      r.fail("equation term count",
             concat(terms, " exceeds the limit of ", FieldEquation::kMaxTerms));
    if (terms > 0) {
      auto equation = std::make_shared<FieldEquation>();
      for (std::uint32_t i = 0; i < terms; ++i) {
        EquationTerm t;
        const int kind = r.i32("equation term kind");
        if (kind < int(EquationKind::Tornado) || kind > int(EquationKind::Downwash))
          r.fail("equation term kind", concat("unknown kind ", kind));
        t.kind = EquationKind(kind);
        t.seed = r.u32("equation term seed");
        for (glm::vec4* v : {&t.a, &t.b, &t.c})
          for (int c = 0; c < 4; ++c)
            (*v)[c] = r.f32("equation term parameter");
        equation->terms.push_back(t);
      }
      update.equation = std::move(equation);
    }
    if (r.boolean("field series")) {
      FieldSeriesRef series;
      series.steps = r.u32("field series steps");
      series.first = r.u32("field series first step");
      series.second = r.u32("field series second step");
      if (series.first >= series.steps || series.second >= series.steps)
        r.fail("field series step", concat("steps ", series.first, " and ", series.second,
                                           " of a series of ", series.steps));
      for (FileIdentity* f : {&series.firstFile, &series.secondFile}) {
        f->present = r.boolean("field series file present");
        f->size = r.u64("field series file size");
        f->modified = std::int64_t(r.u64("field series file time"));
      }
      series.backwards = r.boolean("field series backwards");
      series.loop = r.boolean("field series loop");
      update.series = series;
    }
    p.fieldUpdate = std::make_shared<const FieldUpdate>(std::move(update));
  }
  p.viewer.head.position = vec3(r, "viewer.head.position");
  p.viewer.head.right = vec3(r, "viewer.head.right");
  p.viewer.head.eyeSeparation = r.f32("viewer.head.eye_separation");
  p.viewer.navigation.offset = vec3(r, "viewer.navigation.offset");
  p.viewer.navigation.yawRadians = r.f32("viewer.navigation.yaw");
  p.viewer.navigation.scale = r.f32("viewer.navigation.scale");
  p.fieldBlend = r.f32("field_blend");
  p.lodScale = r.f32("lod_scale");
  if (r.boolean("tracking present")) p.tracking = tracking(r);
  if (r.boolean("wand present")) p.wand = wandRay(r);
  r.finish();
  if (refs) *refs = found;
  return p;
}

}  // namespace sandstorm
