// Copyright contactlaws authors.
//
// The state of libcontactlaws_plugin.so: which mjModel came from which file,
// the tags of each tagged model, and one ContactData per mjData of a tagged
// model. wrappers.cc (the LD_PRELOAD entry points) calls it; every map is
// guarded by one mutex, since a program may load and step on several threads
// (mujoco-simulate steps on its physics thread and deletes on its render
// thread).
//
// Policy: whatever the plugin refuses (a model's tags, a bad
// CONTACTLAWS_LAW, _RESTITUTION, _FRICTION or _MU) is one line on stderr, the
// line `contactlaws run` prints, and the model is left to MuJoCo's own
// contact; the program goes on.

#ifndef CONTACTLAWS_PLUGIN_PLUGIN_H_
#define CONTACTLAWS_PLUGIN_PLUGIN_H_

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <mujoco/mujoco.h>

#include "contactlaws/auto_timestep.h"
#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"
#include "mujoco/visible_contacts.h"

namespace contactlaws::plugin {

// The environment variables the plugin reads (once, at the first tagged
// model): the overrides of `contactlaws run --law ... --restitution ...
// --friction ... --mu ...`.
inline constexpr const char* kLawVariable = "CONTACTLAWS_LAW";
inline constexpr const char* kRestitutionVariable = "CONTACTLAWS_RESTITUTION";
inline constexpr const char* kFrictionVariable = "CONTACTLAWS_FRICTION";
inline constexpr const char* kMuVariable = "CONTACTLAWS_MU";
// `--accuracy TOL` of run: each managed mjData steps with the contact-aware
// timestep (AutoTimestep): MuJoCo is given the data's view of the model
// (ContactData::model_view), the program's options with the step chosen, and
// the program's model is not written. Without it the program's model steps
// as given.
inline constexpr const char* kAccuracyVariable = "CONTACTLAWS_ACCURACY";
// `--settle` of run: CONTACTLAWS_SETTLE=1 moves the bodies a tagged model
// places touching into the static equilibrium of their contacts (Settle,
// settle.h), once per model from its qpos0, and every mjData of it starts
// there (mj_makeData, mj_resetData). One line on stderr says what moved, or
// why nothing could (the scene's positions are then kept).
inline constexpr const char* kSettleVariable = "CONTACTLAWS_SETTLE";
// `--contact-steps auto|N` of run: each managed mjData integrates its
// contacts inside each of the program's steps (ContactData::SetContactSteps,
// docs/timestep.md, "Contact steps"), at the program's own step and
// integrator; with a fixed step only (refused with CONTACTLAWS_ACCURACY).
inline constexpr const char* kContactStepsVariable = "CONTACTLAWS_CONTACT_STEPS";
// 1: a model loaded from a file gets what it lacks of MuJoCo's samples' look
// (render/scene_look.h), as render draws it (contactlaws simulate sets it
// unless --plain)
inline constexpr const char* kLookVariable = "CONTACTLAWS_LOOK";

// The longest step the plugin's auto timestep takes, s: a frame of a 60 Hz
// display. A viewer draws the state between steps, and a free flight's step
// (up to the time to close half a gap, 0.3 s for the paper's drop) would
// freeze the picture and then jump.
inline constexpr double kPluginMaxStep = 1.0 / 60;

// The overrides in the environment, or the one-line refusal of a bad value
// (named as `VARIABLE=VALUE requirement`, as the options are).
struct EnvironmentOverrides {
  Overrides overrides;
  std::optional<double> accuracy;  // CONTACTLAWS_ACCURACY: step with AutoTimestep
  bool settle = false;             // CONTACTLAWS_SETTLE=1
  ContactStepsOptions contact_steps;  // CONTACTLAWS_CONTACT_STEPS (off when unset)
  std::optional<std::string> refusal;
};
EnvironmentOverrides ReadEnvironmentOverrides();

// True when m has a contactlaw: or contactdrive: text entry.
bool HasTags(const mjModel* m);

// One mjData of a tagged model, with its laws.
struct ManagedData {
  ManagedData(const ContactModel& model, mjData* d) : contacts(model, d) {}
  ContactData contacts;
  std::optional<AutoTimestep> auto_step;  // with CONTACTLAWS_ACCURACY
  VisibleContactsOverflow overflow;
  bool divergence_reported = false;
};

// m (loaded from file by mj_loadXML, with vfs) with what it lacks of the
// samples' look, under CONTACTLAWS_LOOK=1: a new model, m deleted; m itself
// otherwise, or when the file cannot be dressed (one line on stderr).
mjModel* WithLook(mjModel* m, const char* file, const mjVFS* vfs);

class Plugin {
 public:
  static Plugin& Get();  // never destroyed: a program may step during exit

  // mj_loadXML / mj_loadModel gave m from file.
  void Loaded(const mjModel* m, const char* file);
  // mj_makeData(m) gave d: a ContactData when m is tagged and accepted.
  void Made(const mjModel* m, mjData* d);
  // mj_resetData(m, d) reset d: the settled positions, with CONTACTLAWS_SETTLE.
  void ResetDone(const mjModel* m, mjData* d);
  // before mj_deleteData(d) / mj_deleteModel(m)
  void Deleting(const mjData* d);
  void DeletingModel(const mjModel* m);

  // d's laws, or nullptr when MuJoCo alone steps d. Valid until d is deleted.
  ManagedData* Find(const mjData* d);

  // After a step of managed: the divergence, once, on stderr.
  void ReportDivergence(ManagedData* managed);

 private:
  struct ModelEntry {
    std::string source = "mjModel";  // the file, as the program named it
    bool resolved = false;           // tags read (the first mj_makeData)
    std::unique_ptr<ContactModel> laws;  // null: untagged or refused
    bool settled = false;                // Settle tried (the first mj_makeData)
    std::vector<mjtNum> settled_qpos;    // with CONTACTLAWS_SETTLE, when it settled
  };
  // entry's settled_qpos from m's qpos0, and the line of what moved (under
  // mutex_).
  void SettleModel(const mjModel* m, ModelEntry* entry);
  // The entry of m, its tags read on first use (under mutex_).
  ModelEntry& Resolve(const mjModel* m);
  // The overrides of the environment; false (and the refusal printed, once)
  // when they are refused.
  bool OverridesAccepted();

  std::mutex mutex_;
  std::unordered_map<const mjModel*, ModelEntry> models_;
  std::unordered_map<const mjData*, std::unique_ptr<ManagedData>> data_;
  std::optional<EnvironmentOverrides> environment_;
};

}  // namespace contactlaws::plugin

#endif  // CONTACTLAWS_PLUGIN_PLUGIN_H_
