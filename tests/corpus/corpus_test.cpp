// Models nobody here wrote: every model file of Assimp's own test corpus (Debian's
// assimp-testmodels, installed by scripts/setup.sh) and three OpenArena levels (Debian's
// openarena-081-maps, each packed alone into a .pk3 when the tests are configured), each opened as
// `shadowlab` opens it. Each must either load, and then give finite maps for every map method, or be
// refused with a reason that names it; never crash or hang the program. One test per folder of the
// corpus, so that ctest spreads them over the cores; each prints a line per file, which
// scripts/corpus_summary.sh counts for the README.
#include <filesystem>
#include <iostream>
#include <set>
#include <gtest/gtest.h>

#include "methods/shadow_inputs.hpp"
#include "registry/method.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

// Images, shaders, text and the like beside the models: a model references them, none is one.
bool auxiliary(const fs::path& file) {
    static const std::set<std::string> kAuxiliary = {
        ".png",  ".jpg",     ".jpeg", ".bmp",      ".tga",      ".dds",    ".gif",     ".ktx",  ".ktx2", ".tif",
        ".tiff", ".psd",     ".hdr",  ".exr",      ".pcx",      ".webp",   ".glsl",    ".vert", ".frag", ".bin",
        ".txt",  ".md",      ".mtl",  ".material", ".skeleton", ".shader", ".program", ".py",   ".json", ".xml",
        ".html", ".license", ".cfg",  ".ini",      ".pdf",      ".wav",    ".mp3",     ".ogg"};
    std::string name = file.filename().string();
    std::transform(name.begin(), name.end(), name.begin(), ::tolower);
    if (name.ends_with(".mesh.xml")) return false;  // an Ogre mesh
    return kAuxiliary.contains(fs::path(name).extension().string()) || name == "readme" || name == "license";
}

std::vector<fs::path> model_files(const fs::path& folder) {
    std::vector<fs::path> files;
    std::error_code error;
    for (const auto& entry : fs::recursive_directory_iterator(folder, error))
        if (entry.is_regular_file() && !auxiliary(entry.path())) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// The folders holding model files, each test's parameter: the corpus's own subfolders (3DS, OBJ,
// glTF2, ...; not those of reference images or parser test texts) and the levels' folder.
std::vector<fs::path> model_folders() {
    std::vector<fs::path> folders;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(SHADOWLAB_ASSIMP_CORPUS, error))
        if (entry.is_directory() && !model_files(entry.path()).empty()) folders.push_back(entry.path());
    if (!model_files(SHADOWLAB_LEVELS).empty()) folders.push_back(SHADOWLAB_LEVELS);
    std::sort(folders.begin(), folders.end());
    return folders;
}

std::size_t corpus_file_count() {
    std::size_t count = 0;
    for (const fs::path& folder : model_folders()) count += model_files(folder).size();
    return count;
}

bool finite(const ShadowMap& map) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(map.world_to_uvz[c][r])) return false;
    return true;
}

// Every map method's setup on the scene; the first one with a non-finite map, or "".
std::string non_finite_method(const Scene& scene) {
    const ShadowInputs inputs = gather_inputs(scene);
    for (const Method& method : all_methods()) {
        if (!method.makes_maps()) continue;
        const ShadowSetup setup =
            method.compute_maps(inputs, resolve_settings(method.name, method.settings, {}), nullptr);
        if (setup.maps.empty() || !std::all_of(setup.maps.begin(), setup.maps.end(), finite)) return method.name;
    }
    return "";
}

TEST(Corpus, IsInstalled) {
    // scripts/setup.sh installs both packages: without them this suite would check nothing.
    EXPECT_GE(corpus_file_count(), 400u) << SHADOWLAB_ASSIMP_CORPUS << " (assimp-testmodels) is missing or cut";
    EXPECT_EQ(model_files(SHADOWLAB_LEVELS).size(), 3u) << SHADOWLAB_LEVELS << " (openarena-081-maps) is missing";
}

// One model of each common format loads, with triangles: a refusal of every file (an importer that
// always fails would pass the folders' test) fails here.
TEST(Corpus, OneModelOfEachCommonFormatLoads) {
    const std::string corpus = SHADOWLAB_ASSIMP_CORPUS;
    const std::vector<std::string> models = {
        corpus + "/OBJ/WusonOBJ.obj",     corpus + "/PLY/Wuson.ply",
        corpus + "/STL/Spider_ascii.stl", corpus + "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
        corpus + "/FBX/box.fbx",          corpus + "/BLEND/box.blend",
        corpus + "/3DS/fels.3ds",         corpus + "/3DS/testFormatDetection",
        corpus + "/Collada/duck.dae",     corpus + "/X/test.x",
        corpus + "/RAW/WithColor.raw",    std::string(SHADOWLAB_LEVELS) + "/oa_dm4.pk3"};
    for (const std::string& model : models) {
        const Scene scene = load_scene(model);
        std::size_t triangles = 0;
        for (const SceneObject& object : scene.objects)
            if (object.mesh) triangles += object.mesh->triangles.size();
        EXPECT_GT(triangles, 0u) << model;
    }
}

class CorpusFolder : public ::testing::TestWithParam<fs::path> {};

TEST_P(CorpusFolder, EveryFileLoadsWithFiniteMapsOrIsRefusedWithAReason) {
    const std::vector<fs::path> files = model_files(GetParam());
    ASSERT_FALSE(files.empty()) << GetParam();
    for (const fs::path& file : files) {
        try {
            const Scene scene = load_scene(file.string());
            const std::string bad = non_finite_method(scene);
            EXPECT_EQ(bad, "") << file << ": a non-finite map";
            std::cout << "corpus\tloaded\t" << file.string() << "\t" << scene.objects.size() << " objects\n";
        } catch (const SceneError& error) {
            EXPECT_FALSE(error.problem().empty()) << file;
            EXPECT_NE(std::string(error.what()).find(file.filename().string()), std::string::npos)
                << "the refusal does not name the file: " << error.what();
            std::cout << "corpus\trefused\t" << file.string() << "\t" << error.problem() << "\n";
        }
    }
}

std::string folder_name(const ::testing::TestParamInfo<fs::path>& info) {
    std::string name = info.param.filename().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Models, CorpusFolder, ::testing::ValuesIn(model_folders()), folder_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusFolder);  // Corpus.IsInstalled fails instead

}  // namespace
}  // namespace shadowlab
