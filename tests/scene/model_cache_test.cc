// Copyright contactlaws authors.
//
// The compiled-scene cache: a cached model is MuJoCo's compile byte for byte;
// an edited scene, an edited file it reads, a damaged entry, a refused scene
// or a scene MuJoCo warns about is compiled again, with MuJoCo's own message.

#include "scene/model_cache.h"

#include <sys/stat.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contactlaws/error.h"
#include "mujoco_test_util.h"

namespace contactlaws {
namespace {

namespace fs = std::filesystem;

constexpr char kBall[] = R"(<mujoco>
  <option timestep="{}"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 1"><freejoint/><geom name="ball" type="sphere" size="0.1"/></body>
  </worldbody>
</mujoco>)";

// MuJoCo's binary file of m: every number of the model.
std::vector<char> Saved(const mjModel* m) {
  std::vector<char> bytes(static_cast<size_t>(mj_sizeModel(m)));
  mj_saveModel(m, nullptr, bytes.data(), static_cast<int>(bytes.size()));
  return bytes;
}

UniqueModel MujocosOwn(const std::string& path) {
  char error[1000] = "";
  UniqueModel m(mj_loadXML(path.c_str(), nullptr, error, sizeof(error)));
  EXPECT_TRUE(m) << error;
  return m;
}

std::string Message(const std::string& path) {
  try {
    LoadModelFile(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

class ModelCacheTest : public testing::MujocoTest {
 protected:
  void SetUp() override {
    MujocoTest::SetUp();
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = ::testing::TempDir() + "/model_cache_" + info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ + "/scenes");
    UseModelCache(dir_ + "/cache");
  }
  void TearDown() override {
    UseModelCache(std::nullopt);
    MujocoTest::TearDown();
  }

  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = dir_ + "/scenes/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  size_t Entries() const {
    if (!fs::exists(dir_ + "/cache")) return 0;
    return static_cast<size_t>(std::distance(fs::directory_iterator(dir_ + "/cache"),
                                             fs::directory_iterator()));
  }
  std::string Entry() const { return fs::directory_iterator(dir_ + "/cache")->path(); }

  std::string dir_;
};

TEST_F(ModelCacheTest, CachedModelIsMujocosCompileByteForByte) {
  const std::string path = Write("ball.xml", fmt::format(kBall, 1e-5));
  const UniqueModel first = LoadModelFile(path);
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kSaved);
  const UniqueModel second = LoadModelFile(path);
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kLoaded);
  EXPECT_EQ(Saved(second.get()), Saved(MujocosOwn(path).get()));
  EXPECT_EQ(Saved(first.get()), Saved(second.get()));
  EXPECT_EQ(Entries(), 1u);
}

TEST_F(ModelCacheTest, EditedSceneIsCompiledAgain) {
  const std::string path = Write("ball.xml", fmt::format(kBall, 1e-5));
  LoadModelFile(path);
  Write("ball.xml", fmt::format(kBall, 2e-5));
  const UniqueModel edited = LoadModelFile(path);
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kSaved);
  EXPECT_EQ(edited->opt.timestep, 2e-5);
  EXPECT_EQ(Saved(LoadModelFile(path).get()), Saved(MujocosOwn(path).get()));
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kLoaded);
}

// A binary STL tetrahedron with edges of length size along the axes.
std::string Tetrahedron(float size) {
  const float v[4][3] = {{0, 0, 0}, {size, 0, 0}, {0, size, 0}, {0, 0, size}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string stl(80, ' ');
  const uint32_t count = 4;
  stl.append(reinterpret_cast<const char*>(&count), sizeof count);
  for (const auto& f : faces) {
    const float normal[3] = {0, 0, 0};
    stl.append(reinterpret_cast<const char*>(normal), sizeof normal);
    for (int k : f) stl.append(reinterpret_cast<const char*>(v[k]), sizeof v[k]);
    stl.append(2, '\0');
  }
  return stl;
}

TEST_F(ModelCacheTest, SceneReadingFilesIsNotCachedAndSeesTheirEdits) {
  Write("tetra.stl", Tetrahedron(0.1f));
  const std::string path = Write("mesh.xml", R"(<mujoco>
  <asset><mesh name="tetra" file="tetra.stl"/></asset>
  <worldbody><body><freejoint/><geom type="mesh" mesh="tetra"/></body></worldbody>
</mujoco>)");
  const double radius = LoadModelFile(path)->geom_rbound[0];
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kNotCached);
  Write("tetra.stl", Tetrahedron(0.2f));
  // the mesh twice as large: its bounding radius doubles
  constexpr double kRounding = 1e-6;  // float vertices, MuJoCo's centring
  EXPECT_NEAR(LoadModelFile(path)->geom_rbound[0], 2 * radius, kRounding * radius);
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kNotCached);

  Write("part.xml", R"(<mujoco><option gravity="0 0 -1"/></mujoco>)");
  const std::string with_include = Write("include.xml", R"(<mujoco>
  <include file="part.xml"/>
  <worldbody><body><freejoint/><geom size="0.1"/></body></worldbody>
</mujoco>)");
  EXPECT_EQ(LoadModelFile(with_include)->opt.gravity[2], -1);
  Write("part.xml", R"(<mujoco><option gravity="0 0 -2"/></mujoco>)");
  EXPECT_EQ(LoadModelFile(with_include)->opt.gravity[2], -2);
  EXPECT_EQ(Entries(), 0u);
}

TEST_F(ModelCacheTest, RefusedSceneIsNotCachedAndGetsMujocosMessage) {
  const std::string path = Write("broken.xml", "<mujoco>\n<worldbody>\n<geom type=\"sphere\">\n</mujoco>");
  const std::string cached = Message(path);
  UseModelCache(std::nullopt);
  EXPECT_EQ(cached, Message(path));
  EXPECT_NE(cached.find("broken.xml: "), std::string::npos) << cached;
  EXPECT_EQ(Entries(), 0u);
}

TEST_F(ModelCacheTest, SceneMujocoWarnsAboutIsNotCached) {
  // MuJoCo's parser warns about a NaN (mju_warning, each time it loads)
  const std::string path = Write("nan.xml", R"(<mujoco>
  <custom><numeric name="n" data="nan"/></custom>
  <worldbody><body><freejoint/><geom size="0.1"/></body></worldbody>
</mujoco>)");
  LoadModelFile(path);
  EXPECT_EQ(ExpectMujocoWarning("NaN"), 1u);
  LoadModelFile(path);
  EXPECT_EQ(ExpectMujocoWarning("NaN"), 1u);
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kNotCached);
  EXPECT_EQ(Entries(), 0u);
}

TEST_F(ModelCacheTest, SensorNoiseSceneIsNotCached) {
  // the compiler seeds rand(), which noisy sensors draw from
  const std::string path = Write("noise.xml", R"(<mujoco>
  <worldbody><body><freejoint/><geom size="0.1"/><site name="s"/></body></worldbody>
  <sensor><accelerometer site="s" noise="0.1"/></sensor>
</mujoco>)");
  LoadModelFile(path);
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kNotCached);
  EXPECT_EQ(Entries(), 0u);
}

TEST_F(ModelCacheTest, DamagedEntryIsCompiledAgain) {
  const std::string path = Write("ball.xml", fmt::format(kBall, 1e-5));
  LoadModelFile(path);
  const std::string entry = Entry();
  const auto size = fs::file_size(entry);
  for (const auto& damage : {std::string("flip"), std::string("truncate")}) {
    if (damage == "flip") {
      std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(static_cast<std::streamoff>(size) - 100);
      f.put('\x7f');
    } else {
      fs::resize_file(entry, size - 8);
    }
    const UniqueModel m = LoadModelFile(path);
    EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kSaved) << damage;
    EXPECT_EQ(Saved(m.get()), Saved(MujocosOwn(path).get())) << damage;
    EXPECT_EQ(fs::file_size(entry), size) << damage << ": written again";
  }
}

TEST_F(ModelCacheTest, OldestEntriesGoPastTheBound) {
  const size_t scenes = kModelCacheMaxEntries + 3;
  std::vector<std::string> paths;
  for (size_t i = 0; i < scenes; ++i) {
    paths.push_back(Write(fmt::format("ball{}.xml", i), fmt::format(kBall, 1e-5 * (1 + i))));
    LoadModelFile(paths.back());
  }
  EXPECT_EQ(Entries(), kModelCacheMaxEntries);
  LoadModelFile(paths.back());
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kLoaded);
  LoadModelFile(paths.front());
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kSaved) << "the oldest was removed";
}

TEST_F(ModelCacheTest, UnwritableDirectoryOnlyCostsTheCompile) {
  const std::string file = Write("not_a_directory", "");
  UseModelCache(file + "/cache");
  const std::string path = Write("ball.xml", fmt::format(kBall, 1e-5));
  EXPECT_EQ(Saved(LoadModelFile(path).get()), Saved(MujocosOwn(path).get()));
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kNotCached);
}

TEST_F(ModelCacheTest, OffLeavesNoEntry) {
  UseModelCache(std::nullopt);
  LoadModelFile(Write("ball.xml", fmt::format(kBall, 1e-5)));
  EXPECT_EQ(LastModelCacheOutcome(), ModelCacheOutcome::kOff);
  EXPECT_EQ(Entries(), 0u);
}

// Sets an environment variable for the scope, then puts back what was there.
class ScopedVariable {
 public:
  explicit ScopedVariable(const char* name) : name_(name) {
    const char* value = std::getenv(name);
    if (value) saved_ = value;
  }
  ~ScopedVariable() {
    if (saved_) {
      setenv(name_, saved_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

TEST(ModelCacheDirectoryTest, FromTheEnvironment) {
  const ScopedVariable home("HOME"), xdg("XDG_CACHE_HOME"), setting("CONTACTLAWS_MODEL_CACHE");
  setenv("HOME", "/home/someone", 1);
  setenv("XDG_CACHE_HOME", "/xdg", 1);
  unsetenv("CONTACTLAWS_MODEL_CACHE");
  EXPECT_EQ(ModelCacheDirectoryFromEnvironment(), "/xdg/contactlaws");
  setenv("XDG_CACHE_HOME", "relative", 1);  // the XDG specification ignores it
  EXPECT_EQ(ModelCacheDirectoryFromEnvironment(), "/home/someone/.cache/contactlaws");
  unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(ModelCacheDirectoryFromEnvironment(), "/home/someone/.cache/contactlaws");
  for (const char* off : {"off", "0"}) {
    setenv("CONTACTLAWS_MODEL_CACHE", off, 1);
    EXPECT_EQ(ModelCacheDirectoryFromEnvironment(), std::nullopt) << off;
  }
  unsetenv("CONTACTLAWS_MODEL_CACHE");
  unsetenv("HOME");
  EXPECT_EQ(ModelCacheDirectoryFromEnvironment(), std::nullopt);
}

TEST(ModelCacheWarningTest, StaysOffWithoutAWarningHandler) {
  // the cache could not tell a scene MuJoCo warns about
  void (*previous)(const char*) = mju_user_warning;
  mju_user_warning = nullptr;
  UseModelCache(::testing::TempDir() + "/model_cache_no_handler");
  EXPECT_FALSE(model_cache::On());
  UseModelCache(std::nullopt);
  mju_user_warning = previous;
}

}  // namespace
}  // namespace contactlaws
