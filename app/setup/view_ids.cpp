#include "app/setup/view_ids.h"

#include "core/support/errors.h"

namespace triwalk {

namespace {

int parseId(const std::string& text, const std::string& name, const std::string& option) {
  size_t used = 0;
  int id = -1;
  try {
    id = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || id < 0) {
    throw InputError(option, "'" + name + "' is not a view id (12 for a sample, p3 for a probe)");
  }
  return id;
}

}  // namespace

const ViewRecord& findView(const Dataset& dataset, const std::string& name, const std::string& option) {
  if (!name.empty() && name[0] == 'p') {
    const int index = dataset.probeIndexOfId(parseId(name.substr(1), name, option));
    if (index < 0) throw InputError(option, "no probe " + name + " in " + dataset.manifestPath().string());
    return dataset.probe(index);
  }
  return dataset.sample(findSampleIndex(dataset, name, option));
}

int findSampleIndex(const Dataset& dataset, const std::string& name, const std::string& option) {
  const int index = dataset.sampleIndexOfId(parseId(name, name, option));
  if (index < 0) throw InputError(option, "no sample " + name + " in " + dataset.manifestPath().string());
  return index;
}

}  // namespace triwalk
