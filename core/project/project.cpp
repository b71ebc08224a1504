#include "core/project/project.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kFormat = "clm3d-project";
constexpr int kVersion = 1;

fs::path normalised(const fs::path& p) {
  return fs::absolute(p).lexically_normal();
}

// Relative to the folder when inside it, absolute otherwise.
std::string stored(const fs::path& folder, const fs::path& p) {
  const fs::path relative = normalised(p).lexically_relative(folder);
  if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
  return normalised(p).generic_string();
}

std::vector<fs::path> readList(JsonFields& doc, const char* key, const Project& project,
                               const fs::path& file) {
  std::vector<fs::path> out;
  const JsonValue* list = doc.find(key);
  if (list == nullptr) return out;
  if (!list->is_array())
    throw InputError(fileMessage(file, std::string("'") + key + "' must be a list"));
  for (const JsonValue& entry : *list) {
    if (!entry.is_string() || entry.get<std::string>().empty()) {
      throw InputError(fileMessage(file, std::string("'") + key + "' must hold non-empty paths"));
    }
    project.addUnique(out, entry.get<std::string>());
  }
  return out;
}

// "tracker": {"model": PATH, "options": {NAME: VALUE}}; a value is a string, number or boolean and
// is kept as the text the command line would take.
void readTracker(JsonFields& doc, Project& project, const fs::path& file) {
  if (!doc.has("tracker")) return;
  JsonFields tracker = doc.object("tracker");
  const auto bad = [&](const std::string& what) {
    throw InputError(fileMessage(file, "\"tracker\" " + what));
  };
  const std::string model = tracker.string("model", std::string(), true);
  if (!model.empty()) project.trackerModel = project.resolve(model);
  const JsonValue* options = tracker.find("options");
  tracker.rejectUnknown();
  if (options == nullptr) return;
  if (!options->is_object()) bad("\"options\" must be an object");
  // The option names are checked against the tracker's table where they are used
  // (trackerSettingsFrom names this file and the option).
  for (const auto& [name, value] : options->items()) {
    if (value.is_string()) {
      project.trackerOptions[name] = value.get<std::string>();
    } else if (value.is_boolean()) {
      project.trackerOptions[name] = value.get<bool>() ? "true" : "false";
    } else if (value.is_number()) {
      project.trackerOptions[name] = value.dump();
    } else {
      bad("option \"" + name + "\" must be a string, number or boolean");
    }
  }
}

// An option's text as JSON: a number or boolean when it reads as one, else a string.
json optionValue(const std::string& text) {
  if (text == "true" || text == "false") return text == "true";
  const json parsed = json::parse(text, nullptr, false);
  if (!parsed.is_discarded() && parsed.is_number()) return parsed;
  return text;
}

}  // namespace

fs::path Project::resolve(const fs::path& p) const {
  return p.is_absolute() ? p.lexically_normal() : (folder / p).lexically_normal();
}

bool Project::addUnique(std::vector<fs::path>& list, const fs::path& p) const {
  const fs::path resolved = resolve(p);
  if (std::find(list.begin(), list.end(), resolved) != list.end()) return false;
  list.push_back(resolved);
  return true;
}

Project loadProject(const fs::path& folderOrFile) {
  const fs::path file =
      fs::is_directory(folderOrFile) ? folderOrFile / Project::kFileName : folderOrFile;
  if (!fs::exists(file)) {
    throw InputError(fileMessage(
        file, "no clm3d project here (" + std::string(Project::kFileName) + " is missing)"));
  }
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  return parseProject(readTextFile(file), folder, file);
}

Project parseProject(std::string_view text, const fs::path& folder, const fs::path& file) {
  const JsonValue doc = parseJsonText(text, file.string());
  if (!doc.is_object() || !doc.contains("format") || !doc.at("format").is_string() ||
      doc.at("format").get<std::string>() != kFormat) {
    throw InputError(
        fileMessage(file, "not a clm3d project (\"format\" must be \"clm3d-project\")"));
  }
  if (!doc.contains("version") || !doc.at("version").is_number_integer() ||
      doc.at("version").get<int>() != kVersion) {
    throw InputError(fileMessage(file, "unsupported project version (this clm3d reads version " +
                                           std::to_string(kVersion) + ")"));
  }
  JsonFields fields(doc, file.string());
  fields.allow({"format", "version"});  // checked above
  Project project;
  project.folder = normalised(folder);
  project.name = fields.string("name", project.folder.filename().string(), true);
  const std::string manifest = fields.string("manifest", std::string(), true);
  if (!manifest.empty()) project.manifest = project.resolve(manifest);
  project.models = readList(fields, "models", project, file);
  project.videos = readList(fields, "videos", project, file);
  project.tracks = readList(fields, "tracks", project, file);
  project.groundTruth = readList(fields, "ground_truth", project, file);
  readTracker(fields, project, file);
  fields.rejectUnknown();
  return project;
}

void saveProject(const Project& project) {
  const fs::path folder = normalised(project.folder);
  fs::create_directories(folder);
  json doc;
  doc["format"] = kFormat;
  doc["version"] = kVersion;
  doc["name"] = project.name.empty() ? folder.filename().string() : project.name;
  doc["manifest"] = project.manifest.empty() ? std::string() : stored(folder, project.manifest);
  const auto list = [&](const std::vector<fs::path>& paths) {
    json out = json::array();
    for (const fs::path& p : paths) out.push_back(stored(folder, project.resolve(p)));
    return out;
  };
  doc["models"] = list(project.models);
  doc["videos"] = list(project.videos);
  doc["tracks"] = list(project.tracks);
  doc["ground_truth"] = list(project.groundTruth);
  if (!project.trackerModel.empty() || !project.trackerOptions.empty()) {
    json tracker = json::object();
    if (!project.trackerModel.empty()) {
      tracker["model"] = stored(folder, project.resolve(project.trackerModel));
    }
    json options = json::object();
    for (const auto& [name, text] : project.trackerOptions) options[name] = optionValue(text);
    tracker["options"] = options;
    doc["tracker"] = tracker;
  }
  writeTextAtomically(folder / Project::kFileName, doc.dump(2) + "\n");
}

Project createProject(const fs::path& folder, const std::string& name) {
  Project project;
  project.folder = normalised(folder);
  if (fs::exists(project.file())) {
    throw InputError(fileMessage(project.file(), "a project exists here already; open it instead"));
  }
  project.name = name.empty() ? project.folder.filename().string() : name;
  saveProject(project);
  return project;
}

}  // namespace clm3d
