// Copyright contactlaws authors.
//
// ContactModel: the tags of one mjModel resolved against it. Built once per
// model (it reads names, groups, radii); immutable afterwards, so any number
// of ContactData (one per mjData, on any threads) can share it.

#ifndef CONTACTLAWS_CONTACT_MODEL_H_
#define CONTACTLAWS_CONTACT_MODEL_H_

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/friction.h"
#include "contactlaws/law.h"

namespace contactlaws {

// ---------------------------------------------------------------------------
// The one exception type of the library: a one-line message that names the
// file, the tag, the key and the value, e.g.
//   "ball.xml: contactlaw:ball-floor: restitution=1.5 must be in [0, 1]".

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// An Error about an option the caller gave: its message names the option by
// its key, as a C++ caller sets it ("settle: body 'box' tips ...",
// SimulationOptions::settle). A front-end that names its options otherwise
// (the command line's --settle, Python's settle=True) takes text() and
// writes each mention its own way.
class OptionError : public Error {
 public:
  // How a mention names the option: by name, as a switch turned on, or
  // given a word ("--columns bodies,joints").
  enum class Form { kName, kSet, kGiven };
  struct Mention {
    Form form = Form::kName;
    std::string key;   // snake_case: "settle", "impact_velocity"
    std::string word;  // kGiven's
  };
  // Where a mention stands in text, in order.
  static constexpr char kMark = '\x1f';

  OptionError(std::string text, std::vector<Mention> mentions);

  const std::string& text() const { return text_; }
  const std::vector<Mention>& mentions() const { return mentions_; }

 private:
  std::string text_;
  std::vector<Mention> mentions_;
};

// ---------------------------------------------------------------------------
// Owning handles for mjModel and mjData, and MJCF loading with messages that
// name the file.

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using UniqueModel = std::unique_ptr<mjModel, ModelDeleter>;
using UniqueData = std::unique_ptr<mjData, DataDeleter>;

// Loads an MJCF file. Throws Error "PATH: <MuJoCo's message>".
UniqueModel LoadModelFile(const std::string& path);

// Loads MJCF text from memory (through MuJoCo's VFS); name stands for the
// file in messages. Throws Error.
UniqueModel LoadModelString(std::string_view xml, const std::string& name = "inline.xml");

// The name of a MuJoCo object, or "<kind><id>" (geom3, body2) when unnamed:
// how every message and CSV column names geoms and bodies.
std::string ObjectName(const mjModel* m, mjtObj type, int id);

// The mjVERSION_HEADER of the MuJoCo library this process runs (222 = 2.2.2).
int MujocoVersion();

// This library's version ("0.1.0").
std::string_view LibraryVersion();

// A numeric contactlaw tag key and its value (Overrides::values).
struct KeyValue {
  std::string key;   // "restitution", "stiffness", "mu", ... (tag_keys: TagValue::kNumber)
  double value = 0;  // in the key's unit
};

// Command-line style overrides applied to every tagged pair before
// validation (contactlaws run --law ... --restitution ...).
struct Overrides {
  std::optional<LawId> law;
  std::optional<double> restitution;
  // c (s/m) of the laws that read it (ReadsDissipation); the others ignore it,
  // as Hertz ignores the restitution
  std::optional<double> dissipation;
  // every tagged pair's friction model, and its mu (mu_static = mu_kinetic)
  std::optional<FrictionKind> friction;
  std::optional<double> mu;
  // key=value words set on every contactlaw tag after its own words (the
  // command line's --set): each replaces the tag's own value of the key or
  // adds it, and is checked as the tag's own words are
  std::vector<std::pair<std::string, std::string>> keys;
  // numeric keys set on every contactlaw tag as values, after keys (a fit's
  // parameters): each replaces the tag's own value of the key or adds it, and
  // is refused outside the key's range as the tag's own value is. With keys
  // or values and a law override, the tag is read under that law (a key it
  // reads, dissipation, is then not refused as the tag's own law's).
  std::vector<KeyValue> values;
};

// One contactlaw tag.
struct PairTag {
  std::string label;   // "ball-floor" for contactlaw:ball-floor
  std::string geom1;   // as written: a name or group:N
  std::string geom2;
  LawId law{};  // hertz unless set
  double restitution = 1.0;
  std::vector<int> pairs;  // indices into ContactModel::pairs()
};

// One geom pair a tag covers (a group tag covers many).
struct GeomPair {
  // ordered as MuJoCo's narrowphase wants: geom_type[geom[0]] <= geom_type[geom[1]]
  std::array<int, 2> geom = {-1, -1};
  std::array<int, 2> body = {-1, -1};
  std::array<int, 2> named = {-1, -1};  // geom1, geom2 in the tag's order
  int tag = -1;          // index into ContactModel::tags()
  int slots = 1;         // most contact points the narrowphase returns for it
  LawParams params;      // resolved (stiffness from materials included)
  // Resolved from the tag, the overrides and the geoms (condim, friction):
  // none when the larger condim is 1 (MuJoCo's frictionless contact).
  FrictionParams friction;
  int condim = 3;           // the larger of the two geoms' condim
  // The mass the default tangential damping sees, kg: m0 m1 / (m0 + m1) of
  // the two bodies' subtree masses (a static or driven body: the other's).
  double friction_mass = 0;
  // The same for the rolling and torsional dampers, kg m^2: each body's
  // largest principal moment of inertia.
  double friction_inertia = 0;
  // A depth beyond this is divergence, not contact: kDivergenceDepthFraction
  // of the smaller geom's size (GeomSize), m; infinite for two planes.
  double depth_limit = 0;
  // Two evaluations of the pair are the same physical contact point when
  // they sit within this distance of each other on either body (m):
  // kContactIdentityFraction of the smaller geom's size.
  double identity_tolerance = 0;
};

// A contact point is matched from one step to the next within this fraction
// of the smaller geom's size (GeomSize): the points of one pair lie at least
// twice that size apart (a box's corners: its smallest full edge), so a
// quarter of it tells them apart with room to spare, and a point may move
// that far on its bodies between two steps (a ball rolling at 10 m/s on a
// 0.1 m radius, 1 ms steps: 1 cm of 2.5 cm).
inline constexpr double kContactIdentityFraction = 0.25;

// The depth at which a run is stopped as diverged, as a fraction of the
// smaller geom's size. The laws come from Hertz's small-deformation theory
// (d much smaller than the radii): at half the radius the model no longer
// describes anything, and a stiff contact that gets there has been stepped
// over, not resolved.
inline constexpr double kDivergenceDepthFraction = 0.5;

// A geom's smallest characteristic size, m: the radius of a sphere, capsule
// or cylinder (or the cylinder's half length when smaller), the smallest
// semi-axis of an ellipsoid or half-size of a box, the bounding radius of a
// mesh; infinite for planes and height fields.
double GeomSize(const mjModel* m, int g);

// A body whose position is prescribed by a contactdrive tag:
//   motion=sine:   p(t) = ref + axis * amplitude * sin(omega t + phase);
//   motion=linear: p(t) = ref + axis * speed * t (a belt: a driven plane).
struct Drive {
  enum class Motion { kSine, kLinear };
  std::string label;
  int body = -1;
  int mocap = -1;  // the body's mocap index
  Motion motion = Motion::kSine;
  std::array<double, 3> ref = {0, 0, 0};
  std::array<double, 3> axis = {0, 0, 1};
  double amplitude = 0.0;  // m
  double omega = 0.0;      // rad/s
  double phase = 0.0;      // rad
  double speed = 0.0;      // m/s (linear)

  void Position(double t, double pos[3]) const;
  void Velocity(double t, double vel[3]) const;
};

class Simulation;

namespace internal {
class ParsedTags;          // src/scene/parsed_tags.h
class ContactModelReader;  // src/scene/contact_model_reader.h
}  // namespace internal

class ContactModel {
 public:
  // Reads and validates the tags of m; source names the file in messages.
  // Throws Error with a one-line message. m must outlive this object.
  explicit ContactModel(const mjModel* m, std::string source = "model",
                        const Overrides& overrides = {});

  ContactModel(const ContactModel&) = delete;
  ContactModel& operator=(const ContactModel&) = delete;

  const mjModel* model() const { return model_; }
  const std::string& source() const { return source_; }
  const std::vector<PairTag>& tags() const { return tags_; }
  const std::vector<GeomPair>& pairs() const { return pairs_; }
  const std::vector<Drive>& drives() const { return drives_; }
  // The most contact points of all pairs at once.
  int slot_count() const { return slot_count_; }
  // One line per tag and pair type whose depth MuJoCo gives with a known
  // limit (docs/geometry.md), "SOURCE: contactlaw:TAG: (g1, g2): REASON";
  // pair types whose depth is wrong are refused instead.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // The tagged pair of two geoms, in either order; -1 when untagged. O(1).
  int FindPair(int g1, int g2) const;

  // The drive of body b, or nullptr.
  const Drive* FindDrive(int body) const {  // inline: asked at every contact point
    const int i = body_drive_[body];
    return i < 0 ? nullptr : &drives_[i];
  }

 private:
  friend class Simulation;  // makes a Scene's from the tags it read once
  friend class internal::ContactModelReader;  // reads the tags into it
  // The tags already read (a Scene's: the same <text> entries as m's).
  ContactModel(const mjModel* m, std::string source, const Overrides& overrides,
               const internal::ParsedTags& tags);

  const mjModel* model_;
  std::string source_;
  Overrides overrides_;
  std::vector<PairTag> tags_;
  std::vector<GeomPair> pairs_;
  std::vector<Drive> drives_;
  std::vector<int> body_drive_;          // body -> drive index or -1
  std::vector<uint8_t> geom_tagged_;     // fast reject in FindPair
  std::unordered_map<uint64_t, int> pair_index_;
  int slot_count_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_CONTACT_MODEL_H_
