#pragma once
// Internal to the io layer: MJCF default classes, as MuJoCo's modeling guide ("Default settings") and XML
// reference (<default>, body childclass) define them, for the elements the MJCF readers use (<geom>, <joint>
// and the <mesh> assets).
//
//  * The top-level <default> of <mujoco> is the class "main"; a <default class="NAME"> nested in another
//    defines the class NAME, which starts from every attribute value of the enclosing class and overrides
//    those it writes itself. Inside a class, <geom .../>, <joint .../> and <mesh .../> give the attribute
//    values of the geoms, joints and meshes of that class.
//  * The class of a <geom> (or <joint>) is its own `class` attribute; without one, the `childclass` of the
//  nearest body
//    that contains it (the geom's own body included, then its ancestors); without one, "main". A <mesh>
//    asset uses its own `class` or "main" (childclass applies to the bodies' elements only).
//  * An attribute the element writes itself wins over its class's.
//  * The orientation of a geom (quat, axisangle, euler, xyaxes, zaxis: alternative ways of writing one
//    thing) is taken whole from the nearest level that writes any of them — the element, then its class,
//    then the enclosing classes — so that a quat on the element replaces an euler of the class.
// MuJoCo has no default values for <inertial> or for the attributes of <body> (other than childclass), so
// those are read as written.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "xml_source.hpp"

namespace poinsot::io::detail {

/// An attribute value and the element that writes it (the element itself or a <geom>/<mesh> of a default
/// class), for messages that point at the right line.
struct MjcfValue {
  const char* text = nullptr;
  const tinyxml2::XMLElement* owner = nullptr;
};

/// The attribute values of one default class for one kind of element: name -> value.
using MjcfClassValues = std::map<std::string, MjcfValue, std::less<>>;

class MjcfDefaults {
 public:
  /// Reads every <default> of the model. Throws InvalidInput (one line naming the element) for a nested
  /// <default> without a class name and for a class defined twice.
  explicit MjcfDefaults(const XmlSource& xml);

  /// The values of class `name` for elements of `kind` ("geom", "joint" or "mesh"); `user` is the element
  /// that asked, for the message. Throws InvalidInput `SOURCE:LINE: <geom> class="NAME": no such default
  /// class` when the model does not define it.
  const MjcfClassValues& values(const std::string& name, const char* kind,
                                const tinyxml2::XMLElement& user) const;

  /// The class of `e`: its `class` attribute, else (when `use_childclass`) the childclass of the nearest
  /// <body> containing it, else "main".
  static std::string class_of(const tinyxml2::XMLElement& e, bool use_childclass);

 private:
  const XmlSource& xml_;
  std::map<std::string, std::map<std::string, MjcfClassValues, std::less<>>, std::less<>> classes_;
};

/// The attributes of one <geom> or <mesh> with its class's values beneath its own.
class MjcfAttributes {
 public:
  MjcfAttributes(const XmlSource& xml, const tinyxml2::XMLElement& e, const MjcfClassValues& class_values);

  /// The value of attribute `name` (see the orientation rule above), or an empty MjcfValue.
  MjcfValue get(const char* name) const;
  /// The value as exactly `count` finite numbers (XmlSource::numbers_attribute on the element that writes
  /// it: its message names that element's line); nothing when absent.
  std::optional<std::vector<double>> numbers(const char* name, std::size_t count) const;

 private:
  const XmlSource& xml_;
  const tinyxml2::XMLElement& e_;
  const MjcfClassValues& class_values_;
  bool own_orientation_ = false;
};

/// The orientation attributes of MJCF: quat and its four alternatives.
inline constexpr const char* kMjcfOrientations[] = {"quat", "axisangle", "euler", "xyaxes", "zaxis"};

}  // namespace poinsot::io::detail
