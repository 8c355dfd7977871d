// A flat JSON object whose fields keep the order they were added in, so output is reproducible.
#ifndef CGAL_POLICIES_APPS_CLI_JSON_OBJECT_H
#define CGAL_POLICIES_APPS_CLI_JSON_OBJECT_H

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace apps {

class Json_object {
 public:
  void add(const std::string& key, const std::string& value) { push(key, quote(value)); }
  void add(const std::string& key, const char* value) { add(key, std::string(value)); }
  void add(const std::string& key, bool value) { push(key, value ? "true" : "false"); }
  void add(const std::string& key, double value) { push(key, format_number(value)); }
  template <typename Integer, typename = std::enable_if_t<std::is_integral<Integer>::value &&
                                                          !std::is_same<Integer, bool>::value>>
  void add(const std::string& key, Integer value) {
    push(key, std::to_string(value));
  }
  void add(const std::string& key, const std::vector<std::string>& values) {
    std::string list = "[";
    for (std::size_t i = 0; i < values.size(); ++i) list += (i ? ", " : "") + quote(values[i]);
    push(key, list + "]");
  }

  // An array of objects, e.g. a report's per-level fields.
  void add(const std::string& key, const std::vector<Json_object>& objects) {
    std::string list = "[";
    for (std::size_t i = 0; i < objects.size(); ++i) list += (i ? ", " : "") + objects[i].str();
    push(key, list + "]");
  }

  // Ten significant digits: stable across runs, and finer than any measurement we report.
  static std::string format_number(double value) {
    if (!std::isfinite(value)) return "null";
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
  }

  std::string str() const {
    std::string text = "{";
    for (std::size_t i = 0; i < m_fields.size(); ++i)
      text += (i ? ", " : "") + quote(m_fields[i].first) + ": " + m_fields[i].second;
    return text + "}";
  }

 private:
  void push(const std::string& key, std::string value) {
    m_fields.emplace_back(key, std::move(value));
  }

  static std::string quote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
      if (c == '"' || c == '\\') {
        out += '\\';
        out += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
        out += escaped;
      } else {
        out += c;
      }
    }
    return out + "\"";
  }

  std::vector<std::pair<std::string, std::string>> m_fields;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_JSON_OBJECT_H
