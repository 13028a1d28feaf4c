#pragma once
// The tests' XML check: tinyxml2 (Debian's libtinyxml2-dev, test-only) reads what the SVG and MJCF
// writers wrote, so that the check is a widely used parser and not one written next to the writers.
// tinyxml2 9.0 accepts a few documents that XML 1.0 does not; parse_xml refuses those too, looking
// at tinyxml2's nodes (or, for control characters, at the bytes):
//   - more than one root element, or text outside it             (<a/><a/>, x<a/>);
//   - entity references other than the five predefined ones and
//     character references                                       (&nbsp;, &amp without ';');
//   - a raw '<' in an attribute value                             (<a b="<"/>);
//   - control characters other than tab, newline and return;
//   - "--" inside a comment or a comment ending in '-', "]]>" in text;
//   - whitespace before the XML declaration;
//   - a DOCTYPE or other <!...> construct (our writers emit none).
// What tinyxml2 also accepts and is not checked here: no whitespace between two attributes
// (<a b="1"c="2"/>; tests/io/mjcf.cpp checks that for MJCF, which holds no text).
// Errors throw std::runtime_error with tinyxml2's message or the rule broken.
#include <tinyxml2.h>

#include <cctype>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace viz_test {

using xml_document = std::unique_ptr<tinyxml2::XMLDocument>;

namespace xml_detail {

[[noreturn]] inline void fail(const std::string& what, int line) {
  throw std::runtime_error("XML: " + what + " (line " + std::to_string(line) + ")");
}

// s[amp] == '&': a predefined entity or a character reference (&#N; or &#xH;) starts there.
inline bool reference_at(std::string_view s, std::size_t amp) {
  const auto semi = s.find(';', amp);
  if (semi == std::string_view::npos) return false;
  const std::string_view name = s.substr(amp + 1, semi - amp - 1);
  if (name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos")
    return true;
  if (name.size() < 2 || name[0] != '#') return false;
  const bool hex = name[1] == 'x';
  const std::string_view digits = name.substr(hex ? 2 : 1);
  if (digits.empty()) return false;
  for (char c : digits) {
    const auto u = static_cast<unsigned char>(c);
    if (!(hex ? std::isxdigit(u) : std::isdigit(u))) return false;
  }
  return true;
}

// A text or attribute value as written (the document parsed without entity processing).
inline void check_raw_value(std::string_view v, bool attribute, const std::string& where,
                            int line) {
  for (std::size_t i = v.find('&'); i != std::string_view::npos; i = v.find('&', i + 1))
    if (!reference_at(v, i))
      fail("'&' that starts no predefined entity or character reference in " + where, line);
  if (attribute && v.find('<') != std::string_view::npos) fail("'<' in " + where, line);
  if (!attribute && v.find("]]>") != std::string_view::npos) fail("']]>' in " + where, line);
}

inline void check_raw_children(const tinyxml2::XMLNode& parent) {
  for (const tinyxml2::XMLNode* c = parent.FirstChild(); c; c = c->NextSibling()) {
    if (const auto* e = c->ToElement()) {
      for (const auto* a = e->FirstAttribute(); a; a = a->Next())
        check_raw_value(a->Value(), true,
                        "attribute " + std::string(a->Name()) + " of <" + e->Name() + ">",
                        a->GetLineNum());
      check_raw_children(*e);
    } else if (const auto* t = c->ToText()) {
      if (!t->CData())
        check_raw_value(t->Value(), false,
                        parent.ToElement()
                            ? "the text of <" + std::string(parent.ToElement()->Name()) + ">"
                            : std::string("text"),
                        t->GetLineNum());
    } else if (const auto* k = c->ToComment()) {
      const std::string_view v = k->Value();
      if (v.find("--") != std::string_view::npos || (!v.empty() && v.back() == '-'))
        fail("'--' in a comment", k->GetLineNum());
    } else if (c->ToUnknown()) {
      fail("<!" + std::string(c->Value()) + "> (DOCTYPE or another construct)", c->GetLineNum());
    }
  }
}

inline xml_document tinyxml2_parse(const std::string& x, bool entities) {
  auto d = std::make_unique<tinyxml2::XMLDocument>(entities, tinyxml2::PRESERVE_WHITESPACE);
  if (d->Parse(x.data(), x.size()) != tinyxml2::XML_SUCCESS)
    throw std::runtime_error(std::string("XML (tinyxml2): ") + d->ErrorStr());
  return d;
}

}  // namespace xml_detail

/// The document read by tinyxml2, entities decoded, after the checks above; throws on any error.
inline xml_document parse_xml(const std::string& x) {
  int line = 1;
  for (char c : x) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 && c != '\t' && c != '\n' && c != '\r')
      xml_detail::fail("control character " + std::to_string(u), line);
    line += c == '\n';
  }
  // The checks of entities look at values as written: a second parse without entity processing.
  const xml_document raw = xml_detail::tinyxml2_parse(x, false);
  int roots = 0;
  for (const tinyxml2::XMLNode* c = raw->FirstChild(); c; c = c->NextSibling()) {
    if (c->ToElement()) {
      if (++roots > 1)
        xml_detail::fail("second root element <" + std::string(c->Value()) + ">", c->GetLineNum());
    } else if (c->ToText()) {
      for (char ch : std::string_view(c->Value()))
        if (!std::isspace(static_cast<unsigned char>(ch)))
          xml_detail::fail("text outside the root element", c->GetLineNum());
    }
  }
  if (roots == 0) throw std::runtime_error("XML: no root element");
  // tinyxml2 refuses a declaration after other nodes but skips whitespace before it.
  if (raw->FirstChild()->ToDeclaration() && x.rfind("<?", 0) != 0 &&
      x.rfind("\xEF\xBB\xBF<?", 0) != 0)
    xml_detail::fail("XML declaration not at the start", 1);
  xml_detail::check_raw_children(*raw);
  return xml_detail::tinyxml2_parse(x, true);
}

struct xml_summary {
  std::string root;
  std::map<std::string, int> elements;  ///< element name -> count
};

inline void count_elements(const tinyxml2::XMLElement& e, std::map<std::string, int>& out) {
  out[e.Name()]++;
  for (const auto* c = e.FirstChildElement(); c; c = c->NextSiblingElement())
    count_elements(*c, out);
}

/// parse_xml, then the root's name and the counts of every element name.
inline xml_summary check_xml(const std::string& x) {
  const xml_document d = parse_xml(x);
  xml_summary out;
  out.root = d->RootElement()->Name();
  count_elements(*d->RootElement(), out.elements);
  return out;
}

}  // namespace viz_test
