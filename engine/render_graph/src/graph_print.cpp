// Text and Graphviz views of the graph: every declared pass (culled ones marked), every access as an
// edge between a pass and a resource version, barriers, lifetimes, heap offsets and GPU times.
#include <cstdio>
#include <sstream>

#include "caustics/render_graph/render_graph.h"
#include "caustics/rhi/format.h"

namespace caustics::rg {
namespace {

std::string formatMs(double ms) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.3f ms", ms);
    return buf;
}

std::string dotEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

std::string barrierText(const GraphDesc& g, const PlannedBarrier& b) {
    std::string s = std::string(resourceKindName(b.kind)) + " '" + g.resources[b.resource].name + "' " +
                    rhi::resourceStateName(b.before) + " -> " + rhi::resourceStateName(b.after);
    if (b.activation) s += b.aliasing ? " (activate, aliased memory)" : " (activate)";
    // The work on either side (None: every stage).
    s += std::string(" [") + rhi::pipelineStagesName(b.srcStages) + " -> " + rhi::pipelineStagesName(b.dstStages) + "]";
    return s;
}

}  // namespace

std::string RenderGraph::printText() const {
    std::ostringstream out;
    const CompiledPlan* plan = this->plan();
    out << "render graph: " << desc_.passes.size() << " passes, " << desc_.resources.size() << " resources";
    if (plan) out << ", " << plan->order.size() << " kept, transient heap " << plan->heapSize << " bytes";
    out << "\n";
    for (uint32_t p = 0; p < desc_.passes.size(); ++p) {
        const PassDecl& pass = desc_.passes[p];
        out << "pass " << p << " '" << pass.name << "'";
        if (plan) out << (plan->passKept[p] ? "" : " [culled]");
        if (pass.sideEffects) out << " [side effects]";
        if (auto ms = timings_.medianMs(pass.name)) out << " " << formatMs(*ms);
        out << "\n";
        if (plan)
            if (const PlannedPass* planned = plan->findPass(p))
                for (const PlannedBarrier& b : planned->barriers) out << "    barrier " << barrierText(desc_, b) << "\n";
        for (const AccessDecl& a : pass.accesses) {
            const ResourceDecl& res = desc_.resources[a.resource];
            out << "    " << (a.write ? "write " : "read  ") << resourceKindName(res.kind) << " '" << res.name << "' v"
                << a.version << " " << accessName(a.access) << "\n";
        }
    }
    if (plan) {
        for (const PlannedBarrier& b : plan->finalBarriers) out << "final barrier " << barrierText(desc_, b) << "\n";
        for (const Dependency& d : plan->dependencies)
            out << "edge '" << desc_.passes[d.producer].name << "' -> '" << desc_.passes[d.consumer].name << "' via '"
                << desc_.resources[d.resource].name << "' v" << d.version << "\n";
    }
    for (uint32_t r = 0; r < desc_.resources.size(); ++r) {
        const ResourceDecl& res = desc_.resources[r];
        out << "resource " << r << " " << resourceKindName(res.kind) << " '" << res.name << "' "
            << (res.imported ? "imported" : "transient");
        if (res.output) out << " output";
        if (res.kind == ResourceKind::Texture)
            out << " " << res.textureDesc.width << "x" << res.textureDesc.height << " "
                << rhi::formatInfo(res.textureDesc.format).name;
        if (res.kind == ResourceKind::Buffer) out << " " << res.bufferDesc.byteSize << " bytes";
        if (plan) {
            const Lifetime& life = plan->lifetimes[r];
            if (life.used()) out << " lifetime [" << life.first << ", " << life.last << "]";
            else out << " unused";
            if (plan->heapOffset[r]) out << " heap [" << *plan->heapOffset[r] << ", +" << plan->memory[r].size << ")";
        }
        out << "\n";
    }
    return out.str();
}

std::string RenderGraph::printGraphviz() const {
    std::ostringstream out;
    const CompiledPlan* plan = this->plan();
    out << "digraph render_graph {\n  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
    for (uint32_t p = 0; p < desc_.passes.size(); ++p) {
        const PassDecl& pass = desc_.passes[p];
        std::string label = dotEscape(pass.name);
        if (auto ms = timings_.medianMs(pass.name)) label += "\\n" + formatMs(*ms);
        bool culled = plan && !plan->passKept[p];
        if (culled) label += "\\n(culled)";
        out << "  p" << p << " [shape=box, label=\"" << label << "\"" << (culled ? ", style=dashed" : "")
            << (pass.sideEffects ? ", peripheries=2" : "") << "];\n";
    }
    // One node per resource version that some pass touches; version 0 of an import is the host's data.
    for (uint32_t r = 0; r < desc_.resources.size(); ++r) {
        const ResourceDecl& res = desc_.resources[r];
        for (uint32_t v = 0; v <= res.latestVersion; ++v) {
            if (v == 0 && !res.imported) continue;
            out << "  r" << r << "v" << v << " [shape=ellipse, label=\"" << dotEscape(res.name) << " v" << v << "\""
                << (res.imported ? ", style=filled, fillcolor=lightgrey" : "")
                << (res.output && v == res.latestVersion ? ", peripheries=2" : "") << "];\n";
        }
    }
    for (uint32_t p = 0; p < desc_.passes.size(); ++p)
        for (const AccessDecl& a : desc_.passes[p].accesses) {
            if (a.write)
                out << "  p" << p << " -> r" << a.resource << "v" << a.version << " [label=\"" << accessName(a.access)
                    << "\", color=red];\n";
            else
                out << "  r" << a.resource << "v" << a.version << " -> p" << p << " [label=\"" << accessName(a.access)
                    << "\"];\n";
        }
    out << "}\n";
    return out.str();
}

}  // namespace caustics::rg
