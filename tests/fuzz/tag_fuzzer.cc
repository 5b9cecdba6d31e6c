// Copyright contactlaws authors.
//
// Fuzz target for the tag parser and scene validation (libFuzzer's entry
// point; replay_main.cc runs the same function over files without libFuzzer).
//
// The input's first line is a header whose first character picks the mode;
// the rest is the body:
//   P  ParsePairTag:  the body's first line is the tag name, the rest its data
//   D  ParseDriveTag: the same
//   S  a scene: each body line "NAME DATA" becomes <text name="NAME" data="DATA"/>
//      in the <custom> of a fixed scene (plane, spheres, a box, a capsule, geom
//      groups, a mocap body, an explicit <pair>, an <exclude>), XML-escaped;
//      the header's second character picks the integrator (e Euler, r RK4,
//      i implicit), its third the command line's --law override (1 to 9,
//      then a to z: AllLaws()[n - 1] when there is one; anything else none),
//      its fourth the --restitution override (0 to 9: n / 9; anything else
//      none) and its fifth the --dissipation override (0 to 9: n / 9 s/m;
//      anything else none); the scene is loaded, its
//      tags resolved, and when they are valid it is stepped a few times with
//      its laws
//   R  the same, but NAME and DATA go in raw: malformed XML, injected elements
//      (but no <size nstack>: see FuzzScene)
// Any other first character picks a mode by its value, so every input means
// something.
//
// The expected outcome of bad input is contactlaws::Error, with a message that
// starts with the file name. Anything else is a finding: a crash, a sanitizer
// report, another exception, a MuJoCo error (mju_user_error aborts here
// rather than exit), or a broken invariant (abort with a message).

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/contactlaws.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace {

constexpr const char* kSceneName = "fuzz.xml";
constexpr int kSteps = 5;

// TAG_FUZZER_VERBOSE=1: say what each input came to (for writing seeds).
bool Verbose() {
  static const bool verbose = std::getenv("TAG_FUZZER_VERBOSE") != nullptr;
  return verbose;
}

void Say(const std::string& what) {
  if (Verbose()) std::fprintf(stderr, "  -> %s\n", what.c_str());
}

[[noreturn]] void Finding(const std::string& what) {
  std::fprintf(stderr, "tag_fuzzer: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

// MuJoCo's default error handler calls exit(), which libFuzzer would not
// report: abort instead. Warnings (a diverging fuzzed law) are expected.
void AbortOnMujocoError(const char* message) { Finding(std::string("MuJoCo error: ") + message); }
void IgnoreMujocoWarning(const char*) {}

void InstallMujocoHandlers() {
  mju_user_error = AbortOnMujocoError;
  mju_user_warning = IgnoreMujocoWarning;
}

// An Error must name the file it is about, on one line.
void CheckError(const contactlaws::Error& e, std::string_view source, bool one_line) {
  const std::string_view message = e.what();
  Say(std::string(message));
  if (message.substr(0, source.size()) != source || message.substr(source.size(), 2) != ": ") {
    Finding("an Error that does not start with '" + std::string(source) + ": ': " +
            std::string(message));
  }
  if (one_line && message.find_first_of("\n\r") != std::string_view::npos) {
    Finding("an Error of more than one line: " + std::string(message));
  }
}

void CheckInRange(const std::optional<double>& v, double low, double high, const char* what) {
  if (v && !(std::isfinite(*v) && *v >= low && *v <= high)) {
    Finding(std::string("parsed ") + what + " out of its range");
  }
}

// (a) the tag parser alone.
void FuzzParser(bool drive, std::string_view body) {
  const size_t newline = body.find('\n');
  const std::string_view name = body.substr(0, newline);
  const std::string_view data =
      newline == std::string_view::npos ? std::string_view() : body.substr(newline + 1);
  const bool one_line = name.find_first_of("\n\r") == std::string_view::npos;
  try {
    if (drive) {
      const contactlaws::DriveTagSpec spec = contactlaws::ParseDriveTag(kSceneName, name, data);
      if (spec.label.empty() || spec.body.empty()) Finding("a drive tag without label or body");
      const double norm = std::sqrt(spec.axis[0] * spec.axis[0] + spec.axis[1] * spec.axis[1] +
                                    spec.axis[2] * spec.axis[2]);
      if (!(std::fabs(norm - 1.0) < 1e-9)) Finding("a drive axis that is not a unit vector");
      if (!std::isfinite(spec.amplitude) || !std::isfinite(spec.omega) ||
          !std::isfinite(spec.phase)) {
        Finding("a drive with a non-finite number");
      }
      Say("valid drive tag " + spec.label);
    } else {
      const contactlaws::internal::PairTagSpec spec =
          contactlaws::internal::ParsePairTag(kSceneName, name, data);
      if (spec.label.empty() || spec.geom1.empty() || spec.geom2.empty() || !spec.law) {
        Finding("a pair tag without label, geoms or law");
      }
      const double inf = HUGE_VAL;
      CheckInRange(spec.restitution, 0, 1, "restitution");
      CheckInRange(spec.exponent, 1, 3, "exponent");
      CheckInRange(spec.stiffness, 0x1p-1074, inf, "stiffness");
      CheckInRange(spec.linear_stiffness, 0x1p-1074, inf, "linear_stiffness");
      CheckInRange(spec.damping, 0, inf, "damping");
      CheckInRange(spec.min_impact_velocity, 0x1p-1074, inf, "min_impact_velocity");
      CheckInRange(spec.poisson1, -1, 0.5, "poisson1");
      CheckInRange(spec.poisson2, -1, 0.5, "poisson2");
      Say("valid pair tag " + spec.label);
    }
  } catch (const contactlaws::Error& e) {
    CheckError(e, kSceneName, one_line);
  }
  // the number parser on its own: finite whenever it answers
  if (std::optional<double> v = contactlaws::ParseNumber(data)) {
    if (!std::isfinite(*v)) Finding("ParseNumber returned a non-finite number");
  }
}

// The fixed scene of (b); {integrator} and {custom} are filled in.
constexpr std::string_view kScene = R"(<mujoco model="fuzz">
  <option timestep="1e-4" integrator="{integrator}" gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <geom name="wall" type="plane" size="1 1 0.1" pos="2 0 1" zaxis="-1 0 0" group="4"/>
    <body name="ball" pos="0 0 0.1001">
      <freejoint/>
      <geom name="ball" type="sphere" size="0.1" mass="1" group="1"/>
    </body>
    <body name="pebble" pos="0.3 0 0.06">
      <freejoint/>
      <geom name="pebble" type="sphere" size="0.05" mass="0.2" group="1"/>
    </body>
    <body name="crate" pos="-0.4 0 0.1">
      <freejoint/>
      <geom name="crate" type="box" size="0.1 0.1 0.1" mass="2" group="2"/>
      <geom name="knob" type="sphere" size="0.03" pos="0 0 0.12" mass="0.1" group="2"/>
    </body>
    <body name="rod" pos="0 0.5 0.05">
      <freejoint/>
      <geom name="rod" type="capsule" size="0.05 0.2" euler="0 90 0" mass="1" group="3"/>
    </body>
    <body name="table" mocap="true" pos="0 -0.6 0.3">
      <geom name="table" type="box" size="0.3 0.3 0.05" pos="0 0 -0.05" group="3"/>
    </body>
  </worldbody>
  <contact>
    <pair geom1="rod" geom2="floor"/>
    <exclude body1="pebble" body2="crate"/>
  </contact>
  <custom>
{custom}  </custom>
</mujoco>
)";

void AppendEscaped(std::string* out, std::string_view text) {
  for (char c : text) {
    switch (c) {
      case '&': *out += "&amp;"; break;
      case '<': *out += "&lt;"; break;
      case '>': *out += "&gt;"; break;
      case '"': *out += "&quot;"; break;
      case '\'': *out += "&apos;"; break;
      default:
        // control characters are not XML: a space (as attribute
        // normalization would make of a tab or a newline)
        *out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
}

std::string Replace(std::string text, std::string_view field, const std::string& value) {
  const size_t at = text.find(field);
  if (at != std::string::npos) text.replace(at, field.size(), value);
  return text;
}

// (b) scene validation, and a few steps of a valid scene.
void FuzzScene(bool raw, std::string_view header, std::string_view body) {
  const char integrator = header.size() > 1 ? header[1] : 'e';
  contactlaws::Overrides overrides;
  if (header.size() > 2) {
    const char c = header[2];
    const int law = c >= '1' && c <= '9' ? c - '1' : c >= 'a' && c <= 'z' ? 9 + (c - 'a') : -1;
    if (law >= 0 && law < static_cast<int>(contactlaws::AllLaws().size())) {
      overrides.law = contactlaws::AllLaws()[law];
    }
  }
  if (header.size() > 3 && header[3] >= '0' && header[3] <= '9') {
    overrides.restitution = (header[3] - '0') / 9.0;
  }
  if (header.size() > 4 && header[4] >= '0' && header[4] <= '9') {
    overrides.dissipation = (header[4] - '0') / 9.0;
  }
  // Raw input can inject any MJCF. A small <size nstack> makes MuJoCo's own
  // mj_step run out of stack (mju_error, then exit) with or without our
  // hooks: MuJoCo's business, not a finding, so such input is skipped.
  if (raw && body.find("nstack") != std::string_view::npos) return;
  std::string custom;
  size_t start = 0;
  while (start < body.size()) {
    size_t end = body.find('\n', start);
    if (end == std::string_view::npos) end = body.size();
    const std::string_view line = body.substr(start, end - start);
    start = end + 1;
    const size_t space = line.find(' ');
    const std::string_view name = line.substr(0, space);
    const std::string_view data =
        space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
    custom += "    <text name=\"";
    if (raw) {
      custom += name;
    } else {
      AppendEscaped(&custom, name);
    }
    custom += "\" data=\"";
    if (raw) {
      custom += data;
    } else {
      AppendEscaped(&custom, data);
    }
    custom += "\"/>\n";
  }
  std::string xml = Replace(std::string(kScene), "{custom}", custom);
  xml = Replace(std::move(xml), "{integrator}",
                integrator == 'r'   ? "RK4"
                : integrator == 'i' ? "implicit"
                                    : "Euler");

  contactlaws::UniqueModel m;
  try {
    m = contactlaws::LoadModelString(xml, kSceneName);
  } catch (const contactlaws::Error& e) {
    CheckError(e, kSceneName, /*one_line=*/true);
    return;
  }
  if (!m) Finding("LoadModelString returned no model and threw nothing");

  std::unique_ptr<contactlaws::ContactModel> laws;
  try {
    laws = std::make_unique<contactlaws::ContactModel>(m.get(), kSceneName, overrides);
  } catch (const contactlaws::Error& e) {
    // raw mode can put a newline in a name (&#10;): only escaped input must
    // give one line
    CheckError(e, kSceneName, /*one_line=*/!raw);
    return;
  }

  // a valid scene: every tag covers pairs that can touch, with valid laws
  for (const contactlaws::PairTag& tag : laws->tags()) {
    if (tag.pairs.empty()) Finding("a tag that covers no pair: " + tag.label);
  }
  for (const contactlaws::GeomPair& pair : laws->pairs()) {
    if (std::optional<contactlaws::ParamError> e = contactlaws::ValidateLawParams(pair.params)) {
      Finding("a resolved pair with invalid parameters: " + e->key);
    }
    if (pair.geom[0] == pair.geom[1]) Finding("a geom paired with itself");
    if (laws->FindPair(pair.geom[1], pair.geom[0]) < 0) Finding("FindPair misses a tagged pair");
  }

  // a few steps with the laws acting (until the run diverges, as the CLI
  // stops), the readings, then again from the start
  contactlaws::UniqueData d(mj_makeData(m.get()));
  if (!d) Finding("mj_makeData failed");
  contactlaws::ContactData contacts(*laws, d.get());
  for (int run = 0; run < 2; ++run) {
    for (int i = 0; i < kSteps && !contacts.divergence(); ++i) contacts.Step();
    for (int tag = 0; tag < static_cast<int>(laws->tags().size()); ++tag) {
      const contactlaws::TagReading reading = contacts.Reading(tag);
      // (a diverged run may have NaN forces: divergence() says so)
      if (reading.depth < 0 || (!contacts.divergence() && !std::isfinite(reading.force))) {
        Finding("a tag reading out of range without a divergence");
      }
    }
    (void)contacts.ElasticEnergy();
    (void)contacts.DissipatedEnergy();
    if (run == 0) {
      mj_resetData(m.get(), d.get());
      contacts.Reset();
    }
  }
  Say("valid scene: " + std::to_string(laws->tags().size()) + " tags, " +
      std::to_string(laws->pairs().size()) + " pairs, " +
      std::to_string(laws->drives().size()) + " drives, " +
      std::to_string(contacts.impacts().size()) + " impacts");
  for (const contactlaws::Episode& impact : contacts.impacts()) {
    if (impact.tag < 0 || impact.tag >= static_cast<int>(laws->tags().size()) ||
        impact.pair < 0 || impact.pair >= static_cast<int>(laws->pairs().size())) {
      Finding("an impact of no tag or pair");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  static const bool installed = (InstallMujocoHandlers(), true);
  (void)installed;
  const std::string_view input(reinterpret_cast<const char*>(bytes), size);
  const size_t newline = input.find('\n');
  const std::string_view header = input.substr(0, newline);
  const std::string_view body =
      newline == std::string_view::npos ? std::string_view() : input.substr(newline + 1);
  char mode = header.empty() ? 'P' : header[0];
  if (mode != 'P' && mode != 'D' && mode != 'S' && mode != 'R') {
    mode = "PDSR"[static_cast<unsigned char>(mode) % 4];
  }
  try {
    switch (mode) {
      case 'P': FuzzParser(false, body); break;
      case 'D': FuzzParser(true, body); break;
      case 'S': FuzzScene(false, header, body); break;
      case 'R': FuzzScene(true, header, body); break;
    }
  } catch (const contactlaws::Error& e) {
    Finding(std::string("an Error escaped where none was expected: ") + e.what());
  } catch (const std::exception& e) {
    Finding(std::string("an exception that is not contactlaws::Error: ") + e.what());
  }
  return 0;
}
