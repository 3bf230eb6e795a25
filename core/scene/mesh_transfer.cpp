#include "scene/mesh_transfer.hpp"

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace shadowlab {
namespace {

class Writer {
public:
    template <class T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    template <class T>
    void put_all(const std::vector<T>& values) {
        put<std::uint64_t>(values.size());
        bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void put_text(const std::string& text) {
        put<std::uint64_t>(text.size());
        bytes_ += text;
    }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

// Every read checks what is left first, so that no count in the bytes can make it read past them.
class Reader {
public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}

    template <class T>
    bool get(T& value) {
        if (bytes_.size() - at_ < sizeof value) return false;
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return true;
    }
    template <class T>
    bool get_all(std::vector<T>& values) {
        std::uint64_t count = 0;
        if (!get(count) || count > (bytes_.size() - at_) / sizeof(T)) return false;
        values.resize(count);
        // An empty vector's data() may be null, which memcpy may not be given even for 0 bytes.
        if (count > 0) std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
        return true;
    }
    bool get_text(std::string& text) {
        std::uint64_t length = 0;
        if (!get(length) || length > bytes_.size() - at_) return false;
        text = bytes_.substr(at_, length);
        at_ += length;
        return true;
    }
    // A count, then that many texts: fails at the first the bytes lack.
    bool get_texts(std::vector<std::string>& texts) {
        std::uint64_t count = 0;
        if (!get(count)) return false;
        for (std::uint64_t i = 0; i < count; ++i)
            if (!get_text(texts.emplace_back())) return false;
        return true;
    }
    // A count, then that many material colours: fails at the first the bytes lack.
    bool get_colour_sources(std::vector<MaterialColourSource>& sources) {
        std::uint64_t count = 0;
        if (!get(count)) return false;
        for (std::uint64_t i = 0; i < count; ++i) {
            MaterialColourSource& source = sources.emplace_back();
            std::uint8_t named = 0;
            if (!get(named) || !get(source.diffuse) || !get_text(source.texture)) return false;
            source.named = named != 0;
        }
        return true;
    }
    bool done() const { return at_ == bytes_.size(); }

private:
    const std::string& bytes_;
    std::size_t at_ = 0;
};

// The surfaces are none or one per triangle.
bool surfaces_parallel(const TriangleMesh& mesh) {
    return mesh.surfaces.empty() || mesh.surfaces.size() == mesh.triangles.size();
}

bool indices_in_range(const TriangleMesh& mesh) {
    const auto count = static_cast<long long>(mesh.vertices.size());
    for (const std::array<int, 3>& t : mesh.triangles)
        for (int index : t)
            if (index < 0 || index >= count) return false;
    return true;
}

}  // namespace

std::string encode_node_meshes(const std::vector<NodeMesh>& nodes) {
    Writer out;
    out.put<std::uint64_t>(nodes.size());
    for (const NodeMesh& node : nodes) {
        out.put_text(node.node_name);
        out.put_all(node.mesh.vertices);
        out.put_all(node.mesh.triangles);
        out.put_all(node.mesh.surfaces);
        out.put<std::uint64_t>(node.mesh.opacity_maps.size());
        for (const std::string& map : node.mesh.opacity_maps) out.put_text(map);
        out.put<std::uint64_t>(node.mesh.colour_sources.size());
        for (const MaterialColourSource& source : node.mesh.colour_sources) {
            out.put<std::uint8_t>(source.named);
            out.put(source.diffuse);
            out.put_text(source.texture);
        }
        out.put<std::uint64_t>(node.mesh.broken_faces_dropped);
    }
    return out.take();
}

std::optional<std::vector<NodeMesh>> decode_node_meshes(const std::string& bytes) {
    Reader in(bytes);
    std::uint64_t count = 0;
    if (!in.get(count)) return std::nullopt;
    std::vector<NodeMesh> nodes;
    for (std::uint64_t i = 0; i < count; ++i) {
        NodeMesh node;
        std::uint64_t broken = 0;
        if (!in.get_text(node.node_name) || !in.get_all(node.mesh.vertices) || !in.get_all(node.mesh.triangles) ||
            !in.get_all(node.mesh.surfaces) || !in.get_texts(node.mesh.opacity_maps) ||
            !in.get_colour_sources(node.mesh.colour_sources) || !in.get(broken) || !indices_in_range(node.mesh) ||
            !surfaces_parallel(node.mesh))
            return std::nullopt;
        node.mesh.broken_faces_dropped = broken;
        nodes.push_back(std::move(node));
    }
    if (!in.done()) return std::nullopt;
    return nodes;
}

}  // namespace shadowlab
