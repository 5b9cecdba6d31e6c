// Copyright contactlaws authors.

#include "mujoco/hooks.h"

#include <atomic>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>

#include "contactlaws/contact_data.h"
#include "contactlaws/contact_model.h"

namespace contactlaws {
namespace {

int FilterHook(const mjModel* m, mjData* d, int g1, int g2);
void PassiveHook(const mjModel* m, mjData* d);

struct Registry {
  std::shared_mutex mutex;
  std::unordered_map<const mjData*, ContactData*> data;
  std::atomic<uint64_t> generation{1};  // bumped by every (un)registration
  // the callbacks found when the first ContactData came: written under the
  // mutex, read by the hooks without it (a thread stepping an mjData of its
  // own may be inside a hook while another registers)
  std::atomic<mjfConFilt> previous_filter{nullptr};
  std::atomic<mjfGeneric> previous_passive{nullptr};
};

Registry& GetRegistry() {
  static Registry* registry = new Registry;  // never destroyed: hooks may run late
  return *registry;
}

// Per-thread cache of the last lookup: the hooks run per geom pair, so the
// common case (the same mjData again) takes no lock.
struct LookupCache {
  const mjData* d = nullptr;
  ContactData* contact_data = nullptr;
  uint64_t generation = 0;
};
thread_local LookupCache lookup_cache;

ContactData* Lookup(const mjModel* m, const mjData* d) {
  Registry& registry = GetRegistry();
  const uint64_t generation = registry.generation.load(std::memory_order_acquire);
  if (lookup_cache.d != d || lookup_cache.generation != generation) {
    std::shared_lock lock(registry.mutex);
    auto found = registry.data.find(d);
    lookup_cache.d = d;
    lookup_cache.contact_data = found == registry.data.end() ? nullptr : found->second;
    lookup_cache.generation = registry.generation.load(std::memory_order_acquire);
  }
  // d's ContactData when m is its model, or the view it steps with
  ContactData* cd = lookup_cache.contact_data;
  return cd && (cd->model().model() == m || cd->model_view() == m) ? cd : nullptr;
}

// Gives back the callbacks found before ours, unless somebody replaced ours
// since (under registry.mutex).
void RestoreCallbacks(const Registry& registry) {
  if (mjcb_contactfilter == FilterHook) mjcb_contactfilter = registry.previous_filter.load();
  if (mjcb_passive == PassiveHook) mjcb_passive = registry.previous_passive.load();
}

}  // namespace

void RegisterContactData(mjData* d, ContactData* cd) {
  Registry& registry = GetRegistry();
  std::unique_lock lock(registry.mutex);
  if (!registry.data.emplace(d, cd).second) {
    throw Error("this mjData already has a ContactData");
  }
  if (registry.data.size() == 1) {
    registry.previous_filter.store(mjcb_contactfilter, std::memory_order_release);
    registry.previous_passive.store(mjcb_passive, std::memory_order_release);
    mjcb_contactfilter = FilterHook;
    mjcb_passive = PassiveHook;
  }
  registry.generation.fetch_add(1, std::memory_order_acq_rel);
}

void UnregisterContactData(mjData* d) {
  Registry& registry = GetRegistry();
  std::unique_lock lock(registry.mutex);
  registry.data.erase(d);
  if (registry.data.empty()) {
    // previous_* stay: a hook MuJoCo entered just before this still chains
    // to them
    RestoreCallbacks(registry);
  }
  registry.generation.fetch_add(1, std::memory_order_acq_rel);
}

namespace {

// At exit, or when a shared build of the library is unloaded, the callbacks
// found before are given back even if ContactData objects were leaked.
struct RestoreAtUnload {
  ~RestoreAtUnload() {
    Registry& registry = GetRegistry();
    std::unique_lock lock(registry.mutex);
    if (!registry.data.empty()) RestoreCallbacks(registry);
  }
} restore_at_unload;

}  // namespace

namespace internal {
struct HookCalls {
  static bool ClaimPair(ContactData* cd, int g1, int g2) { return cd->ClaimPair(g1, g2); }
  static void ApplyForces(ContactData* cd) { cd->ApplyForces(); }
};
}  // namespace internal

namespace {

int FilterHook(const mjModel* m, mjData* d, int g1, int g2) {
  // tagged: no MuJoCo constraint, the passive hook applies the law
  if (ContactData* cd = Lookup(m, d); cd && internal::HookCalls::ClaimPair(cd, g1, g2)) return 1;
  mjfConFilt previous = GetRegistry().previous_filter.load(std::memory_order_acquire);
  return previous ? previous(m, d, g1, g2) : DefaultContactFilter(m, g1, g2);
}

void PassiveHook(const mjModel* m, mjData* d) {
  if (mjfGeneric previous = GetRegistry().previous_passive.load(std::memory_order_acquire)) {
    previous(m, d);
  }
  if (ContactData* cd = Lookup(m, d)) internal::HookCalls::ApplyForces(cd);
}

}  // namespace

int DefaultContactFilter(const mjModel* m, int g1, int g2) {
  // contype/conaffinity: at least one direction must match
  if (!(m->geom_contype[g1] & m->geom_conaffinity[g2]) &&
      !(m->geom_contype[g2] & m->geom_conaffinity[g1])) {
    return 1;
  }
  // geoms of the same weld body never collide
  const int weld1 = m->body_weldid[m->geom_bodyid[g1]];
  const int weld2 = m->body_weldid[m->geom_bodyid[g2]];
  if (weld1 == weld2) return 1;
  // parent and child (weld) bodies, unless either is the world or the
  // filterparent flag is disabled
  const int parent1 = m->body_weldid[m->body_parentid[weld1]];
  const int parent2 = m->body_weldid[m->body_parentid[weld2]];
  const bool filter_parent =
      !(m->opt.disableflags & mjDSBL_FILTERPARENT) && weld1 && weld2;
  if (filter_parent && (weld1 == parent2 || weld2 == parent1)) return 1;
  return 0;
}

bool HasUntaggedContacts(const ContactModel& cm) {
  const mjModel* m = cm.model();
  if (m->npair > 0) return true;
  for (int g1 = 0; g1 < m->ngeom; ++g1) {
    for (int g2 = g1 + 1; g2 < m->ngeom; ++g2) {
      if (!DefaultContactFilter(m, g1, g2) && cm.FindPair(g1, g2) < 0) return true;
    }
  }
  return false;
}

}  // namespace contactlaws
