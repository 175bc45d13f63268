#include "struct_layout.h"

#include <regex>

namespace caustics::test {
namespace {

std::vector<StructMember> readMembers(const std::string& body) {
    std::vector<StructMember> members;
    static const std::regex decl("(\\w+)\\s+([^;]+);");
    for (std::sregex_iterator it(body.begin(), body.end(), decl), end; it != end; ++it) {
        // `float4 c0, c1, c2, c3;` declares four members; `uint words[4];` an array of four.
        std::string names = (*it)[2];
        static const std::regex name("(\\w+)\\s*(?:\\[\\s*(\\d+)\\s*\\])?\\s*(?::\\s*\\w+)?");
        for (std::sregex_iterator n(names.begin(), names.end(), name); n != end; ++n)
            members.push_back({(*it)[1], (*n)[2].matched ? uint32_t(std::stoul((*n)[2])) : 1u});
    }
    return members;
}

// Components (4 bytes each) of a built-in scalar/vector/matrix type; 0 if not built in.
uint32_t builtinComponents(const std::string& t) {
    static const std::regex vec("(float|uint|int|bool|half)([234])?|([iub]?vec)([234])|(mat)([234])|float([234])x([234])");
    std::smatch m;
    if (!std::regex_match(t, m, vec)) return 0;
    if (m[1].matched) return m[2].matched ? uint32_t(std::stoul(m[2])) : 1u;
    if (m[3].matched) return uint32_t(std::stoul(m[4]));
    if (m[5].matched) return uint32_t(std::stoul(m[6])) * uint32_t(std::stoul(m[6]));
    return uint32_t(std::stoul(m[7])) * uint32_t(std::stoul(m[8]));
}

uint32_t alignUp(uint32_t v, uint32_t a) { return (v + a - 1) / a * a; }

StructLayoutResult layoutMembers(const std::vector<StructMember>& members, const StructTable& structs, LayoutRules rules,
                                 int depth);

StructLayoutResult layoutType(const std::string& type, const StructTable& structs, LayoutRules rules, int depth) {
    StructLayoutResult r;
    if (uint32_t c = builtinComponents(type)) {
        r.bytes = 4 * c;
        bool matrix = c > 4;
        if (rules == LayoutRules::Std430) r.alignment = matrix ? 16 : (c == 3 ? 16 : 4 * c);
        else if (rules == LayoutRules::HlslCbuffer) r.alignment = matrix ? 16 : 4;
        return r;
    }
    if (type == "BuiltInTriangleIntersectionAttributes") { r.bytes = 8; return r; }   // float2 barycentrics
    auto it = structs.find(type);
    if (it == structs.end() || depth > 8) {
        r.problem = "cannot size type '" + type + "'";
        return r;
    }
    r = layoutMembers(it->second, structs, rules, depth + 1);
    if (rules == LayoutRules::HlslCbuffer) r.alignment = 16;   // a struct starts a new register
    if (rules != LayoutRules::Scalar) r.bytes = alignUp(r.bytes, r.alignment);
    return r;
}

StructLayoutResult layoutMembers(const std::vector<StructMember>& members, const StructTable& structs, LayoutRules rules,
                                 int depth) {
    StructLayoutResult out;
    for (const StructMember& m : members) {
        StructLayoutResult e = layoutType(m.type, structs, rules, depth);
        if (!e.problem.empty()) return e;
        uint32_t align = e.alignment, stride = e.bytes;
        if (m.count > 1 && rules != LayoutRules::Scalar) {
            if (rules == LayoutRules::HlslCbuffer) align = 16;   // every cbuffer array element starts a register
            stride = alignUp(e.bytes, align);
        }
        uint32_t offset = alignUp(out.bytes, align);
        // HLSL constant buffers: a member that would straddle a 16-byte register starts the next one.
        if (rules == LayoutRules::HlslCbuffer && offset / 16 != (offset + e.bytes - 1) / 16) offset = alignUp(offset, 16);
        out.bytes = offset + stride * (m.count - 1) + e.bytes;
        out.alignment = std::max(out.alignment, align);
    }
    return out;
}

}  // namespace

StructTable readStructs(const std::string& text) {
    StructTable table;
    static const std::regex def("\\bstruct\\s+(\\w+)\\s*\\{([^}]*)\\}");
    for (std::sregex_iterator it(text.begin(), text.end(), def), end; it != end; ++it)
        table.emplace((*it)[1], readMembers((*it)[2]));
    return table;
}

StructLayoutResult structSize(const std::string& type, const StructTable& structs, LayoutRules rules) {
    if (!type.empty() && type.front() == '{')
        return layoutMembers(readMembers(type.substr(1, type.rfind('}') - 1)), structs, rules, 0);
    auto it = structs.find(type);   // the outermost struct: no tail padding
    if (it != structs.end()) return layoutMembers(it->second, structs, rules, 1);
    return layoutType(type, structs, rules, 0);
}

}  // namespace caustics::test
