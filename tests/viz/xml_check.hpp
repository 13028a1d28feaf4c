#pragma once
// A minimal XML well-formedness checker for the SVG tests: elements nest and close in order,
// attribute values are quoted, entities are the five predefined or numeric ones, one root element.
// Returns the counts of every element name; throws std::runtime_error describing the first error.
#include <cctype>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace viz_test {

struct xml_summary {
  std::string root;
  std::map<std::string, int> elements;  ///< element name -> count
};

inline void check_entities(const std::string& s, std::size_t at) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '<')
      throw std::runtime_error("'<' in text or attribute near offset " + std::to_string(at + i));
    if (s[i] != '&') continue;
    const auto e = s.find(';', i);
    if (e == std::string::npos)
      throw std::runtime_error("unterminated entity near offset " + std::to_string(at + i));
    const std::string ent = s.substr(i + 1, e - i - 1);
    if (!(ent == "amp" || ent == "lt" || ent == "gt" || ent == "quot" || ent == "apos" ||
          (ent.size() > 1 && ent[0] == '#')))
      throw std::runtime_error("unknown entity &" + ent + "; near offset " +
                               std::to_string(at + i));
  }
}

inline xml_summary check_xml(const std::string& x) {
  xml_summary out;
  std::vector<std::string> stack;
  std::size_t i = 0;
  bool root_closed = false;
  auto fail = [&](const std::string& m) {
    throw std::runtime_error(m + " at offset " + std::to_string(i));
  };
  while (i < x.size()) {
    if (x[i] != '<') {
      const auto e = x.find('<', i);
      const std::string text = x.substr(i, e == std::string::npos ? std::string::npos : e - i);
      if (stack.empty()) {
        for (char c : text)
          if (!std::isspace(static_cast<unsigned char>(c))) fail("text outside the root element");
      } else {
        check_entities(text, i);
      }
      if (e == std::string::npos) break;
      i = e;
      continue;
    }
    if (x.compare(i, 5, "<?xml") == 0) {
      if (i != 0) fail("XML declaration not at the start");
      const auto e = x.find("?>", i);
      if (e == std::string::npos) fail("unterminated declaration");
      i = e + 2;
      continue;
    }
    if (x.compare(i, 4, "<!--") == 0) {
      const auto e = x.find("-->", i);
      if (e == std::string::npos) fail("unterminated comment");
      i = e + 3;
      continue;
    }
    if (x.compare(i, 2, "</") == 0) {
      const auto e = x.find('>', i);
      if (e == std::string::npos) fail("unterminated end tag");
      std::string name = x.substr(i + 2, e - i - 2);
      while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
        name.pop_back();
      if (stack.empty() || stack.back() != name)
        fail("end tag </" + name + "> does not match <" + (stack.empty() ? "" : stack.back()) +
             ">");
      stack.pop_back();
      if (stack.empty()) root_closed = true;
      i = e + 1;
      continue;
    }
    // Start tag.
    std::size_t j = i + 1;
    while (j < x.size() && (std::isalnum(static_cast<unsigned char>(x[j])) || x[j] == '-' ||
                            x[j] == '_' || x[j] == ':'))
      ++j;
    const std::string name = x.substr(i + 1, j - i - 1);
    if (name.empty()) fail("empty element name");
    if (stack.empty() && (root_closed || !out.root.empty()))
      fail("second root element <" + name + ">");
    if (stack.empty()) out.root = name;
    out.elements[name]++;
    bool self_close = false;
    while (true) {
      while (j < x.size() && std::isspace(static_cast<unsigned char>(x[j]))) ++j;
      if (j >= x.size()) fail("unterminated start tag <" + name + ">");
      if (x[j] == '>') {
        ++j;
        break;
      }
      if (x.compare(j, 2, "/>") == 0) {
        j += 2;
        self_close = true;
        break;
      }
      std::size_t a = j;
      while (j < x.size() && (std::isalnum(static_cast<unsigned char>(x[j])) || x[j] == '-' ||
                              x[j] == '_' || x[j] == ':'))
        ++j;
      if (a == j) fail("bad attribute in <" + name + ">");
      if (j >= x.size() || x[j] != '=') fail("attribute without value in <" + name + ">");
      ++j;
      if (j >= x.size() || (x[j] != '"' && x[j] != '\''))
        fail("unquoted attribute in <" + name + ">");
      const char q = x[j];
      const auto e = x.find(q, j + 1);
      if (e == std::string::npos) fail("unterminated attribute in <" + name + ">");
      check_entities(x.substr(j + 1, e - j - 1), j + 1);
      j = e + 1;
    }
    if (!self_close)
      stack.push_back(name);
    else if (stack.empty())
      root_closed = true;
    i = j;
  }
  if (!stack.empty())
    throw std::runtime_error("unclosed element <" + stack.back() + "> at end of document");
  if (out.root.empty()) throw std::runtime_error("no root element");
  return out;
}

}  // namespace viz_test
