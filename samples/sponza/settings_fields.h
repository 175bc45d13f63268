#pragma once
// CausticsSettings fields by name, for the viewer's script (`set exposure 4`) and its error messages.
// Values are parsed strictly; CausticsSettings::validate() then checks ranges.
#include <string>
#include <vector>

#include "caustics/caustics_settings.h"

namespace caustics::sample {

// Field names accepted by setSettingsField (the C++ member names).
const std::vector<std::string>& settingsFieldNames();

// Sets one field from text: numbers, true/false/on/off, aov names (final, direct, caustics, first,
// second, albedo, normal, depth), sphere policies (footprint, world). Errors name the field and value.
Status setSettingsField(CausticsSettings& settings, const std::string& field, const std::string& value);

const char* causticsAovName(CausticsAov aov);

// The whole of `text` as a finite number; the error starts with `what` (a field or "file:line").
Result<double> parseFiniteNumber(const std::string& what, const std::string& text);

}  // namespace caustics::sample
