// Copyright contactlaws authors.

#include "plugin/plugin.h"

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "contactlaws/law.h"
#include "sim/settle.h"
#include "contactlaws/simulation.h"
#include "laws/param_range.h"
#include "render/scene_look.h"
#include "scene/number.h"
#include "scene/tags.h"

namespace contactlaws::plugin {
namespace {

// "contactlaws: plugin: FILE: LABEL (GEOM1, GEOM2: LAW, e = E); ...": the
// tagged pairs as resolved (overrides included), and the driven bodies.
std::string ActivationLine(const std::string& source, const ContactModel& laws) {
  std::string line = fmt::format("contactlaws: plugin: {}:", source);
  const char* separator = " ";
  for (const PairTag& tag : laws.tags()) {
    line += fmt::format("{}{} ({}, {}: {}", separator, tag.label, tag.geom1, tag.geom2,
                        LawName(tag.law));
    if (!IsElastic(tag.law)) line += fmt::format(", e = {}", tag.restitution);
    // the friction of the tag's first pair (a group tag's pairs may differ)
    const FrictionParams& f = laws.pairs()[tag.pairs.front()].friction;
    if (f.kind != FrictionKind::kNone) {
      line += fmt::format(", {} mu {}", FrictionName(f.kind), f.mu_static);
      if (f.mu_kinetic != f.mu_static) line += fmt::format("/{}", f.mu_kinetic);
    }
    line += ")";
    separator = "; ";
  }
  for (const Drive& drive : laws.drives()) {
    line += fmt::format("{}driven body {}", separator, drive.label);
    separator = "; ";
  }
  return line;
}

}  // namespace

EnvironmentOverrides ReadEnvironmentOverrides() {
  EnvironmentOverrides result;
  if (const char* law = std::getenv(kLawVariable)) {
    result.overrides.law = ParseLawName(law);
    if (!result.overrides.law) {
      result.refusal = fmt::format("{}={} is not a law ({})", kLawVariable, law, LawNameList());
      return result;
    }
  }
  if (const char* text = std::getenv(kRestitutionVariable)) {
    const std::optional<double> e = ParseNumber(text);
    if (!e) {
      result.refusal = fmt::format("{}={} is not a finite number", kRestitutionVariable, text);
      return result;
    } else if (!kUnitRange.Contains(*e)) {
      result.refusal = fmt::format("{}={} {}", kRestitutionVariable, *e, kUnitRange.Requirement());
      return result;
    }
    result.overrides.restitution = *e;
  }
  if (const char* name = std::getenv(kFrictionVariable)) {
    result.overrides.friction = ParseFrictionName(name);
    if (!result.overrides.friction) {
      result.refusal = fmt::format("{}={} is not a friction model ({}){}", kFrictionVariable, name,
                                   FrictionNameList(), FrictionSuggestion(name));
      return result;
    }
  }
  if (const char* text = std::getenv(kMuVariable)) {
    const std::optional<double> mu = ParseNumber(text);
    if (!mu) {
      result.refusal = fmt::format("{}={} is not a finite number", kMuVariable, text);
    } else if (!kNonNegativeRange.Contains(*mu)) {
      result.refusal = fmt::format("{}={} {}", kMuVariable, *mu, kNonNegativeRange.Requirement());
    } else {
      result.overrides.mu = *mu;
    }
  }
  if (const char* text = std::getenv(kAccuracyVariable)) {
    const std::optional<double> tol = ParseNumber(text);
    if (!tol) {
      result.refusal = fmt::format("{}={} is not a finite number", kAccuracyVariable, text);
    } else if (!(*tol > 0 && *tol <= kMaxAccuracy)) {
      result.refusal = fmt::format("{}={} must be in (0, {}]", kAccuracyVariable, *tol,
                                   kMaxAccuracy);
    } else {
      result.accuracy = *tol;
    }
  }
  if (const char* text = std::getenv(kContactStepsVariable); text && !result.refusal) {
    const std::optional<int> substeps = ParseContactSteps(text);
    if (!substeps) {
      result.refusal =
          fmt::format("{}={} {}", kContactStepsVariable, text, kContactStepsRequirement);
      return result;
    }
    result.contact_steps.substeps = *substeps;
    if (result.accuracy) {
      result.refusal = fmt::format("{}={} goes with the program's fixed step, not with {}",
                                   kContactStepsVariable, text, kAccuracyVariable);
      return result;
    }
  }
  if (const char* text = std::getenv(kSettleVariable)) {
    if (std::string_view(text) != "1") {
      result.refusal = fmt::format("{}={} must be 1 (or unset)", kSettleVariable, text);
    } else {
      result.settle = true;
    }
  }
  return result;
}

bool HasTags(const mjModel* m) {
  for (int i = 0; i < m->ntext; ++i) {
    const std::string_view name = m->names + m->name_textadr[i];
    if (name.rfind(kPairTagPrefix, 0) == 0 || name.rfind(kDriveTagPrefix, 0) == 0) return true;
  }
  return false;
}

mjModel* WithLook(mjModel* m, const char* file, const mjVFS* vfs) {
  const char* look = std::getenv(kLookVariable);
  if (!m || !file || vfs || !look || std::string_view(look) != "1") return m;
  const render::LookPlan plan = render::PlanLook(m);
  if (plan.empty()) return m;
  try {
    UniqueModel dressed = render::Dressed(m, file, plan);
    mj_deleteModel(m);
    return dressed.release();
  } catch (const Error& e) {
    std::fprintf(stderr, "contactlaws: %s\n", e.what());
    return m;
  }
}

Plugin& Plugin::Get() {
  static Plugin* plugin = new Plugin;
  return *plugin;
}

void Plugin::Loaded(const mjModel* m, const char* file) {
  if (!m) return;
  std::lock_guard lock(mutex_);
  ModelEntry& entry = models_[m];
  entry = ModelEntry{};
  if (file) entry.source = file;
}

bool Plugin::OverridesAccepted() {
  if (!environment_) {
    environment_ = ReadEnvironmentOverrides();
    if (environment_->refusal) {
      std::fprintf(stderr, "contactlaws: %s\n", environment_->refusal->c_str());
    }
  }
  return !environment_->refusal;
}

Plugin::ModelEntry& Plugin::Resolve(const mjModel* m) {
  ModelEntry& entry = models_[m];
  if (entry.resolved) return entry;
  entry.resolved = true;
  if (!HasTags(m) || !OverridesAccepted()) return entry;
  try {
    entry.laws = std::make_unique<ContactModel>(m, entry.source, environment_->overrides);
    std::fprintf(stderr, "%s\n", ActivationLine(entry.source, *entry.laws).c_str());
  } catch (const Error& e) {
    std::fprintf(stderr, "contactlaws: %s\n", e.what());
  }
  return entry;
}

void Plugin::SettleModel(const mjModel* m, ModelEntry* entry) {
  try {
    // the model is the program's: shared with the run, not owned
    SimulationOptions options;
    options.overrides = environment_->overrides;
    Simulation sim(std::shared_ptr<const mjModel>(m, [](const mjModel*) {}), entry->source,
                   options);
    // the program's data start at qpos0 (mj_makeData, mj_resetData), not at
    // a keyframe
    mju_copy(sim.data()->qpos, m->qpos0, m->nq);
    const SettleReport report = Settle(&sim);
    entry->settled_qpos.assign(sim.data()->qpos, sim.data()->qpos + m->nq);
    std::fprintf(stderr, "contactlaws: plugin: %s: %s\n", entry->source.c_str(),
                 report.Line().c_str());
  } catch (const Error& e) {
    std::fprintf(stderr, "contactlaws: %s (the scene's positions kept)\n", e.what());
  }
}

void Plugin::Made(const mjModel* m, mjData* d) {
  if (!m || !d) return;
  std::lock_guard lock(mutex_);
  ModelEntry& entry = Resolve(m);
  if (!entry.laws) return;
  if (environment_->settle && !entry.settled) {
    entry.settled = true;
    SettleModel(m, &entry);
  }
  if (!entry.settled_qpos.empty()) mju_copy(d->qpos, entry.settled_qpos.data(), m->nq);
  auto managed = std::make_unique<ManagedData>(*entry.laws, d);
  if (environment_->accuracy) {
    AutoTimestepOptions options;
    options.accuracy = *environment_->accuracy;
    managed->auto_step.emplace(managed->contacts, options);
  }
  if (environment_->contact_steps.enabled()) {
    managed->contacts.SetContactSteps(environment_->contact_steps);
  }
  data_[d] = std::move(managed);
}

void Plugin::ResetDone(const mjModel* m, mjData* d) {
  std::lock_guard lock(mutex_);
  const auto found = models_.find(m);
  if (found == models_.end() || found->second.settled_qpos.empty()) return;
  mju_copy(d->qpos, found->second.settled_qpos.data(), m->nq);
}

void Plugin::Deleting(const mjData* d) {
  std::lock_guard lock(mutex_);
  data_.erase(d);
}

void Plugin::DeletingModel(const mjModel* m) {
  std::lock_guard lock(mutex_);
  // data of m still alive lose their laws before the laws go
  for (auto it = data_.begin(); it != data_.end();) {
    if (it->second->contacts.model().model() == m) {
      it = data_.erase(it);
    } else {
      ++it;
    }
  }
  models_.erase(m);
}

ManagedData* Plugin::Find(const mjData* d) {
  std::lock_guard lock(mutex_);
  auto found = data_.find(d);
  return found == data_.end() ? nullptr : found->second.get();
}

void Plugin::ReportDivergence(ManagedData* managed) {
  const std::optional<Divergence>& divergence = managed->contacts.divergence();
  if (!divergence) {
    managed->divergence_reported = false;  // forgotten (reset): report the next one
    return;
  }
  if (managed->divergence_reported) return;
  managed->divergence_reported = true;
  std::fprintf(stderr, "contactlaws: %s: diverged at t = %.6g s: %s (the state is not to be "
               "trusted)\n", managed->contacts.model().source().c_str(), divergence->time,
               divergence->what.c_str());
}

}  // namespace contactlaws::plugin
