#include "methods/engine_conventions.hpp"

namespace shadowlab {

SettingSpec storage_setting() {
    return {.name = "storage",
            .description =
                "each matrix's 16 numbers: auto (GLSL's mat4 by columns, HLSL's float4x4 and JSON's rows by "
                "rows), column_major or row_major",
            .default_value = "auto",
            .choices = {"auto", "column_major", "row_major"}};
}

SettingSpec clip_depth_setting() {
    return {.name = "clip_depth",
            .description = "the engine's clip depth z / w: minus_one_to_one (OpenGL) or zero_to_one (Direct3D, Vulkan)",
            .default_value = "minus_one_to_one",
            .choices = {"minus_one_to_one", "zero_to_one"}};
}

SettingSpec reversed_z_setting() {
    return {.name = "reversed_z",
            .description = "on: z / w is 1 at the near plane and falls toward the far one",
            .default_value = "off",
            .choices = {"off", "on"}};
}

MatrixStorage storage_of(const Settings& s) {
    const std::string& storage = s.choice("storage");
    if (storage == "column_major") return MatrixStorage::column_major;
    return storage == "row_major" ? MatrixStorage::row_major : MatrixStorage::automatic;
}

ClipDepth clip_depth_of(const Settings& s) {
    return s.choice("clip_depth") == "zero_to_one" ? ClipDepth::zero_to_one : ClipDepth::minus_one_to_one;
}

bool reversed_z_of(const Settings& s) { return s.choice("reversed_z") == "on"; }

}  // namespace shadowlab
