#include "mjcf_defaults.hpp"

#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

constexpr const char* kMain = "main";
constexpr const char* kKinds[] = {"geom", "mesh", "joint"};

bool is_orientation(std::string_view name) {
  for (const char* o : kMjcfOrientations)
    if (name == o) return true;
  return false;
}

bool writes_orientation(const XMLElement& e) {
  for (const char* o : kMjcfOrientations)
    if (e.Attribute(o) != nullptr) return true;
  return false;
}

/// Writes the attributes of `e` (a <geom> or <mesh> inside a <default>) over `values`; an orientation written
/// by `e` replaces the inherited one whole.
void overlay(const XMLElement& e, MjcfClassValues& values) {
  if (writes_orientation(e)) {
    for (const char* o : kMjcfOrientations)
      values.erase(std::string(o));
  }
  for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::string_view name = a->Name();
    if (name == "class" || name == "name") continue;  // not attributes a class can give
    values.insert_or_assign(std::string(name), MjcfValue{a->Value(), &e});
  }
}

}  // namespace

MjcfDefaults::MjcfDefaults(const XmlSource& xml) : xml_(xml) {
  for (const char* kind : kKinds)
    classes_[kMain][kind];
  // Pre-order over the <default> tree, file order (an explicit stack: the nesting depth is the file's):
  // a class is complete before the classes nested in it copy it.
  std::vector<std::pair<const XMLElement*, std::string>> stack;  // (<default>, parent class or "")
  std::vector<const XMLElement*> top;
  for (const XMLElement* d = xml.root()->FirstChildElement("default"); d != nullptr;
       d = d->NextSiblingElement("default"))
    top.push_back(d);
  for (auto it = top.rbegin(); it != top.rend(); ++it)
    stack.emplace_back(*it, "");
  while (!stack.empty()) {
    const auto [d, parent] = stack.back();
    stack.pop_back();
    std::string name = kMain;  // the top-level <default> is "main", whether it names itself so or not
    if (!parent.empty()) {
      const char* c = d->Attribute("class");
      if (c == nullptr || *c == '\0') {
        throw InvalidInput(fmt::format(
            "{}: nested <default> without class; expected <default class=\"NAME\">", xml_.where(*d)));
      }
      name = c;
      if (classes_.contains(name)) {
        throw InvalidInput(
            fmt::format("{} class=\"{}\": the class is defined twice; expected one <default> per class",
                        xml_.where(*d), one_line(name)));
      }
      auto copy = classes_.at(parent);
      classes_.emplace(name, std::move(copy));
    }
    auto& kinds = classes_.at(name);
    for (const char* kind : kKinds) {
      for (const XMLElement* e = d->FirstChildElement(kind); e != nullptr; e = e->NextSiblingElement(kind))
        overlay(*e, kinds.at(kind));
    }
    std::vector<const XMLElement*> nested;
    for (const XMLElement* c = d->FirstChildElement("default"); c != nullptr;
         c = c->NextSiblingElement("default"))
      nested.push_back(c);
    for (auto it = nested.rbegin(); it != nested.rend(); ++it)
      stack.emplace_back(*it, name);
  }
}

const MjcfClassValues& MjcfDefaults::values(const std::string& name, const char* kind,
                                            const XMLElement& user) const {
  const auto it = classes_.find(name);
  if (it == classes_.end()) {
    throw InvalidInput(
        fmt::format("{} class=\"{}\": no such default class; expected a class defined by "
                    "<default class=\"NAME\">",
                    xml_.where(user), one_line(name)));
  }
  return it->second.at(kind);
}

std::string MjcfDefaults::class_of(const XMLElement& e, bool use_childclass) {
  if (const char* c = e.Attribute("class")) return c;
  if (use_childclass) {
    for (const tinyxml2::XMLNode* p = &e; p != nullptr; p = p->Parent()) {
      const XMLElement* pe = p->ToElement();
      if (pe == nullptr) break;
      if (std::string_view(pe->Name()) == "body") {
        if (const char* c = pe->Attribute("childclass")) return c;
      }
    }
  }
  return kMain;
}

MjcfAttributes::MjcfAttributes(const XmlSource& xml, const XMLElement& e, const MjcfClassValues& class_values)
    : xml_(xml), e_(e), class_values_(class_values), own_orientation_(writes_orientation(e)) {}

MjcfValue MjcfAttributes::get(const char* name) const {
  if (const char* v = e_.Attribute(name)) return {v, &e_};
  if (own_orientation_ && is_orientation(name)) return {};  // the element's orientation replaces the class's
  const auto it = class_values_.find(std::string_view(name));
  return it != class_values_.end() ? it->second : MjcfValue{};
}

std::optional<std::vector<double>> MjcfAttributes::numbers(const char* name, std::size_t count) const {
  const MjcfValue v = get(name);
  if (v.text == nullptr) return std::nullopt;
  return xml_.numbers_attribute(*v.owner, name, count);
}

}  // namespace poinsot::io::detail
