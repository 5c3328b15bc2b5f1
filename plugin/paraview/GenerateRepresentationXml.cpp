// SPDX-License-Identifier: BSD-3-Clause
// Writes ShadingLabRepresentation.xml, the ServerManager XML of the
// "ShadingLab Surface" representation, from the settings table
// (shadinglab/render/Settings.h) at build time: every property, its
// default, range or choices and documentation come from the table, as the
// GLSL #defines come from the C++ enums. Each property calls one of the
// representation's generic setters with the setting's key first
// (ServerManager's initial_string).
#include "shadinglab/render/Settings.h"

#include <cctype>
#include <fstream>
#include <iostream>
#include <sstream>

namespace sr = shadinglab::render;

namespace
{

/// What the last render chose, read back as an information property (the
/// representation's Get<name>), listed after the setting `after`.
struct ChoiceReport
{
  const char* after;
  const char* name;
  const char* documentation;
};
constexpr ChoiceReport kChoiceReports[] = {
  { "max-error", "AutoChoice",
    "Auto shading mode: what the last render chose for each block and why (predicted error "
    "and cost of each mode). Empty in the other modes." },
  { "backend", "BackendChoice",
    "The backend the last render drew each block with; for Auto, why (the OpenGL renderer, "
    "hardware or a software rasterizer, and the polygon count against the crossover)." },
};

std::string Escape(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    switch (c)
    {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string Repeat(const std::string& value, int count)
{
  std::string out;
  for (int i = 0; i < count; ++i)
  {
    out += (i ? " " : "") + value;
  }
  return out;
}

std::string Numbers(const std::vector<double>& values, int count)
{
  std::ostringstream s;
  s.precision(10);
  for (int i = 0; i < count; ++i)
  {
    s << (i ? " " : "") << (i < static_cast<int>(values.size()) ? values[i] : values.back());
  }
  return s.str();
}

/// Whether ParaView's own Surface representation has a property of this name
/// too: from ParaView 5.13 on its normals computation brings FeatureAngle.
/// Ours then says override="1", twice: in the proxy (replacing the inherited
/// definition; without it ParaView 6.1 crashes merging the two) and where it
/// is exposed (replacing ParaView's in the panel without a warning). The
/// Extension's ShareProperties keeps the two in step.
bool AlsoInParaViewSurface(const sr::SettingRow& row)
{
  return row.property == "FeatureAngle";
}

std::string Override(const sr::SettingRow& row)
{
  return AlsoInParaViewSurface(row) ? " override=\"1\"" : "";
}

int ParaViewCount(const sr::SettingRow& row)
{
  return row.paraviewCount > 0 ? row.paraviewCount : row.maxCount;
}

/// The default as ParaView shows it: a choice's label, else the value.
std::string DefaultLabel(const sr::SettingRow& row)
{
  const std::string key = sr::DefaultText(row);
  for (const auto& c : row.choices)
  {
    if (c.key == key)
    {
      return c.label;
    }
  }
  return key;
}

std::string Documentation(const sr::SettingRow& row)
{
  std::string doc = row.doc;
  doc[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(doc[0])));
  if (row.kind == sr::SettingKind::Real || row.kind == sr::SettingKind::Integer)
  {
    doc += ". Range " + sr::RangeText(row);
  }
  const std::string def = DefaultLabel(row);
  return Escape(
    doc + ". Default: " + (def.empty() ? "none" : def) + ". (setting '" + row.key + "')");
}

void Property(std::ostream& out, const sr::SettingRow& row)
{
  const std::string head = " name=\"" + row.property + "\" label=\"" + Escape(row.label) +
    "\" initial_string=\"" + row.key + "\"" + Override(row);
  const sr::SettingValue def = row.get(sr::Settings{});
  switch (row.kind)
  {
    case sr::SettingKind::Choice:
      out << "      <IntVectorProperty" << head
          << " command=\"SetIntSetting\" number_of_elements=\"1\" default_values=\""
          << def.numbers[0] << "\">\n        <EnumerationDomain name=\"enum\">";
      for (size_t i = 0; i < row.choices.size(); ++i)
      {
        out << "<Entry value=\"" << i << "\" text=\"" << Escape(row.choices[i].label) << "\"/>";
      }
      out << "</EnumerationDomain>\n";
      out << "        <Documentation>" << Documentation(row) << "</Documentation>\n"
          << "      </IntVectorProperty>\n";
      break;
    case sr::SettingKind::Flag:
    case sr::SettingKind::Integer:
      out << "      <IntVectorProperty" << head
          << " command=\"SetIntSetting\" number_of_elements=\"1\" default_values=\""
          << def.numbers[0] << "\">\n";
      if (row.kind == sr::SettingKind::Flag)
      {
        out << "        <BooleanDomain name=\"bool\"/>\n";
      }
      else
      {
        out << "        <IntRangeDomain name=\"range\" min=\"" << row.min << "\" max=\"" << row.max
            << "\"/>\n";
      }
      out << "        <Documentation>" << Documentation(row) << "</Documentation>\n"
          << "      </IntVectorProperty>\n";
      break;
    case sr::SettingKind::Real:
    {
      const int n = ParaViewCount(row);
      std::ostringstream lo, hi;
      lo.precision(10);
      hi.precision(10);
      lo << row.min;
      hi << row.max;
      out << "      <DoubleVectorProperty" << head << " command=\"SetRealSetting" << n
          << "\" number_of_elements=\"" << n << "\" default_values=\"" << Numbers(def.numbers, n)
          << "\">\n        <DoubleRangeDomain name=\"range\" min=\"" << Repeat(lo.str(), n)
          << "\" max=\"" << Repeat(hi.str(), n) << "\"/>\n";
      if (row.key == "max-error")
      {
        // The budget is auto mode's: shown only while the mode is Auto.
        const sr::SettingRow* mode = sr::FindSetting("mode");
        size_t autoIndex = 0;
        while (autoIndex < mode->choices.size() && mode->choices[autoIndex].key != "auto")
        {
          ++autoIndex;
        }
        out << "        <Hints><PropertyWidgetDecorator type=\"GenericDecorator\" mode=\"visibility\" "
               "property=\"" << mode->property << "\" value=\"" << autoIndex << "\"/></Hints>\n";
      }
      out << "        <Documentation>" << Documentation(row) << "</Documentation>\n"
          << "      </DoubleVectorProperty>\n";
      break;
    }
    case sr::SettingKind::Text:
    {
      out << "      <StringVectorProperty" << head
          << " command=\"SetTextSetting\" number_of_elements=\"1\" default_values=\""
          << Escape(DefaultLabel(row)) << "\">\n";
      if (row.choices.empty())
      {
        // Free text is a file name (--nk): ParaView's file chooser, on the
        // server's file system.
        out << "        <FileListDomain name=\"files\"/>\n"
            << "        <Hints><FileChooser extensions=\"yml yaml\" "
               "file_description=\"refractiveindex.info optical constants\"/></Hints>\n";
      }
      else
      {
        out << "        <StringListDomain name=\"list\">";
        for (const auto& c : row.choices)
        {
          out << "<String value=\"" << Escape(c.label) << "\"/>";
        }
        out << "</StringListDomain>\n";
      }
      out << "        <Documentation>" << Documentation(row) << "</Documentation>\n"
          << "      </StringVectorProperty>\n";
      break;
    }
  }
}

void Extension(std::ostream& out, const std::string& representation)
{
  out << "    <Extension name=\"" << representation << "\">\n"
      << "      <Documentation>Adds \"ShadingLab Surface\" to the representations of "
      << representation << ".</Documentation>\n"
      << "      <RepresentationType subproxy=\"ShadingLabSurfaceRepresentation\" "
         "text=\"ShadingLab Surface\" subtype=\"Surface\"/>\n"
      << "      <SubProxy>\n"
      << "        <Proxy name=\"ShadingLabSurfaceRepresentation\" proxygroup=\"representations\" "
         "proxyname=\"ShadingLabSurfaceRepresentation\"/>\n"
      << "        <ShareProperties subproxy=\"SurfaceRepresentation\">\n"
      << "          <Exception name=\"Input\"/>\n"
      << "          <Exception name=\"Visibility\"/>\n"
      << "          <Exception name=\"Representation\"/>\n"
      << "        </ShareProperties>\n"
      << "        <ExposedProperties>\n"
      << "          <PropertyGroup label=\"ShadingLab\">\n";
  for (const auto& row : sr::SettingsTable())
  {
    if (row.frontEnds & sr::kParaView)
    {
      out << "            <Property name=\"" << row.property << "\"" << Override(row) << "/>\n";
      for (const ChoiceReport& report : kChoiceReports)
      {
        if (row.key == report.after)
        {
          out << "            <Property name=\"" << report.name << "\"/>\n";
        }
      }
    }
  }
  out << "            <Hints>\n"
      << "              <PropertyWidgetDecorator type=\"GenericDecorator\" mode=\"visibility\" "
         "property=\"Representation\" value=\"ShadingLab Surface\"/>\n"
      << "            </Hints>\n"
      << "          </PropertyGroup>\n"
      << "        </ExposedProperties>\n"
      << "      </SubProxy>\n"
      << "    </Extension>\n";
}

} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: GenerateRepresentationXml OUT.xml\n";
    return 2;
  }
  std::ostringstream out;
  out << "<!-- Generated from plugin/render/src/SettingsTable.cpp by "
         "plugin/paraview/GenerateRepresentationXml.cpp: do not edit. -->\n"
      << "<ServerManagerConfiguration>\n  <ProxyGroup name=\"representations\">\n"
      << "    <RepresentationProxy name=\"ShadingLabSurfaceRepresentation\"\n"
      << "      class=\"vtkShadingLabSurfaceRepresentation\"\n"
      << "      processes=\"client|renderserver|dataserver\"\n"
      << "      base_proxygroup=\"representations\"\n"
      << "      base_proxyname=\"SurfaceRepresentation\">\n"
      << "      <Documentation>\n"
      << "        ParaView's Surface representation drawn by the ShadingLab mapper: the\n"
      << "        shading mode (flat, Gouraud, Phong, fast Phong, auto) and the reflectance\n"
      << "        model (Lambert, Phong, Blinn-Phong, Cook-Torrance, Lommel-Seeliger) chosen\n"
      << "        separately. Colouring by a data array gives the diffuse albedo.\n"
      << "      </Documentation>\n";
  for (const auto& row : sr::SettingsTable())
  {
    if (!(row.frontEnds & sr::kParaView))
    {
      continue;
    }
    Property(out, row);
    for (const ChoiceReport& report : kChoiceReports)
    {
      if (row.key == report.after)
      {
        out << "      <StringVectorProperty name=\"" << report.name << "\" command=\"Get"
            << report.name << "\" information_only=\"1\" panel_visibility=\"never\">\n"
            << "        <SimpleStringInformationHelper/>\n"
            << "        <Documentation>" << report.documentation << "</Documentation>\n"
            << "      </StringVectorProperty>\n";
      }
    }
  }
  out << "    </RepresentationProxy>\n\n";
  for (const char* base : { "GeometryRepresentation", "UnstructuredGridRepresentation",
         "UniformGridRepresentation", "StructuredGridRepresentation" })
  {
    Extension(out, base);
  }
  out << "  </ProxyGroup>\n</ServerManagerConfiguration>\n";

  // Rewritten only when it changed, so the plugin is not rebuilt for nothing.
  const std::string text = out.str();
  {
    std::ifstream old(argv[1]);
    std::stringstream have;
    have << old.rdbuf();
    if (old && have.str() == text)
    {
      return 0;
    }
  }
  std::ofstream file(argv[1]);
  file << text;
  return file ? 0 : 1;
}
