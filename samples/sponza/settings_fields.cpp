#include "settings_fields.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <map>

namespace caustics::sample {
namespace {

Result<double> parseNumber(const std::string& field, const std::string& text) {
    return parseFiniteNumber("set " + field, text);
}

Result<uint32_t> parseCount(const std::string& field, const std::string& text) {
    uint32_t v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec == std::errc::result_out_of_range) return makeError("set " + field + ": " + text + " is out of range");
    if (ec != std::errc() || end != text.data() + text.size())
        return makeError("set " + field + ": '" + text + "' is not a whole number");
    return v;
}

Result<bool> parseBool(const std::string& field, const std::string& text) {
    if (text == "true" || text == "on" || text == "1") return true;
    if (text == "false" || text == "off" || text == "0") return false;
    return makeError("set " + field + ": '" + text + "' is not on/off");
}

constexpr CausticsAov kAovs[] = {CausticsAov::Final, CausticsAov::Direct, CausticsAov::Caustics, CausticsAov::FirstType,
                                 CausticsAov::SecondType, CausticsAov::Albedo, CausticsAov::Normal, CausticsAov::Depth};

using Setter = std::function<Status(CausticsSettings&, const std::string& field, const std::string& value)>;

Setter countField(uint32_t CausticsSettings::*member) {
    return [member](CausticsSettings& s, const std::string& f, const std::string& v) -> Status {
        CAUSTICS_TRY(s.*member, parseCount(f, v));
        return okStatus();
    };
}
Setter floatField(float CausticsSettings::*member) {
    return [member](CausticsSettings& s, const std::string& f, const std::string& v) -> Status {
        CAUSTICS_TRY(double d, parseNumber(f, v));
        s.*member = float(d);
        return okStatus();
    };
}
Setter boolField(bool CausticsSettings::*member) {
    return [member](CausticsSettings& s, const std::string& f, const std::string& v) -> Status {
        CAUSTICS_TRY(s.*member, parseBool(f, v));
        return okStatus();
    };
}

const std::map<std::string, Setter>& setters() {
    static const std::map<std::string, Setter> table = {
        {"mapResolution", countField(&CausticsSettings::mapResolution)},
        {"raysPerTexel", floatField(&CausticsSettings::raysPerTexel)},
        {"photonsPerFrame", countField(&CausticsSettings::photonsPerFrame)},
        {"causticTimeTargetMs", floatField(&CausticsSettings::causticTimeTargetMs)},
        {"causticReceiverReach", floatField(&CausticsSettings::causticReceiverReach)},
        {"maxSpecularDepth", countField(&CausticsSettings::maxSpecularDepth)},
        {"russianRoulette", boolField(&CausticsSettings::russianRoulette)},
        {"secondType", boolField(&CausticsSettings::secondType)},
        {"mapOccluders", boolField(&CausticsSettings::mapOccluders)},
        {"sphereRadiusPolicy",
         [](CausticsSettings& s, const std::string& f, const std::string& v) -> Status {
             if (v == "footprint") s.sphereRadiusPolicy = SphereRadiusPolicy::PixelFootprint;
             else if (v == "world") s.sphereRadiusPolicy = SphereRadiusPolicy::FixedWorld;
             else return makeError("set " + f + ": '" + v + "' is not footprint or world");
             return okStatus();
         }},
        {"sphereRadiusScale", floatField(&CausticsSettings::sphereRadiusScale)},
        {"sphereWorldRadius", floatField(&CausticsSettings::sphereWorldRadius)},
        {"sphereMinMagnification", floatField(&CausticsSettings::sphereMinMagnification)},
        {"sphereMaxMagnification", floatField(&CausticsSettings::sphereMaxMagnification)},
        {"sphereMinRadius", floatField(&CausticsSettings::sphereMinRadius)},
        {"sphereMaxRadius", floatField(&CausticsSettings::sphereMaxRadius)},
        {"maxStoredHits", countField(&CausticsSettings::maxStoredHits)},
        {"secondTypeSplitLobes", boolField(&CausticsSettings::secondTypeSplitLobes)},
        {"filter", boolField(&CausticsSettings::filter)},
        {"filterMaxHistory", countField(&CausticsSettings::filterMaxHistory)},
        {"filterPoolTiles", countField(&CausticsSettings::filterPoolTiles)},
        {"filterCasterMotion", boolField(&CausticsSettings::filterCasterMotion)},
        {"filterSecondTypeApart", boolField(&CausticsSettings::filterSecondTypeApart)},
        {"atrousIterations", countField(&CausticsSettings::atrousIterations)},
        {"filterLuminanceSigma", floatField(&CausticsSettings::filterLuminanceSigma)},
        {"exposure", floatField(&CausticsSettings::exposure)},
        {"framesInFlight", countField(&CausticsSettings::framesInFlight)},
        {"seed", countField(&CausticsSettings::seed)},
        {"aov",
         [](CausticsSettings& s, const std::string& f, const std::string& v) -> Status {
             for (CausticsAov aov : kAovs)
                 if (v == causticsAovName(aov)) {
                     s.aov = aov;
                     return okStatus();
                 }
             return makeError("set " + f + ": '" + v + "' is not final, direct, caustics, first, second, albedo, normal or depth");
         }},
        {"causticsEnabled", boolField(&CausticsSettings::causticsEnabled)},
    };
    return table;
}

}  // namespace

Result<double> parseFiniteNumber(const std::string& what, const std::string& text) {
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
        return makeError(what + ": '" + text + "' is not a number");
    return v;
}

const char* causticsAovName(CausticsAov aov) {
    switch (aov) {
        case CausticsAov::Final: return "final";
        case CausticsAov::Direct: return "direct";
        case CausticsAov::Caustics: return "caustics";
        case CausticsAov::FirstType: return "first";
        case CausticsAov::SecondType: return "second";
        case CausticsAov::Albedo: return "albedo";
        case CausticsAov::Normal: return "normal";
        case CausticsAov::Depth: return "depth";
    }
    return "?";
}

const std::vector<std::string>& settingsFieldNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const auto& [name, setter] : setters()) n.push_back(name);
        return n;
    }();
    return names;
}

Status setSettingsField(CausticsSettings& settings, const std::string& field, const std::string& value) {
    auto it = setters().find(field);
    if (it == setters().end()) {
        std::string list;
        for (const std::string& n : settingsFieldNames()) list += (list.empty() ? "" : ", ") + n;
        return makeError("set: unknown CausticsSettings field '" + field + "' (one of " + list + ")");
    }
    CausticsSettings changed = settings;
    CAUSTICS_CHECK(it->second(changed, field, value));
    CAUSTICS_CHECK(changed.validate());
    settings = changed;
    return okStatus();
}

}  // namespace caustics::sample
