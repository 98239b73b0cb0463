#pragma once
// Reading and writing bonl's files: the JSON model format (io/model_json.hpp). Needs nlohmann_json,
// so it is not in bonl.hpp: link bonl::io to use it.

#include "io/model_json.hpp"
