#include "pqCloudColorMapBehavior.h"

#include "CloudFilterNames.h"
#include "Estimation/OutputTable.h"
#include "Estimation/ShapeClass.h"
#include "Lines/LineTypes.h"

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkPVDataSetAttributesInformation.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMProxy.h"
#include "vtkSMTransferFunctionManager.h"
#include "vtkSMTransferFunctionProxy.h"

#include <array>
#include <cctype>
#include <string>
#include <vector>

namespace
{
using Color = std::array<double, 3>;

/// A color per pcurv::ShapeClass, by code: gray undetermined, pale flat,
/// warm convex (dome red, ridge orange), cool concave (cup blue, valley
/// cyan), saddle green: the features stand out on the flat ground.
constexpr std::array<Color, static_cast<int>(pcurv::ShapeClass::Count)> ShapeClassColors = { {
  { 0.45, 0.45, 0.45 },
  { 0.90, 0.88, 0.80 },
  { 0.84, 0.15, 0.16 },
  { 0.17, 0.32, 0.80 },
  { 1.00, 0.60, 0.10 },
  { 0.30, 0.80, 0.90 },
  { 0.20, 0.65, 0.25 },
} };

/// A color per pcurv::LineKind, by code. The lines are drawn over points
/// colored by a curvature with a blue-white-red map, ridges where it is red
/// and valleys where it is blue: ridges orange and valleys green stand out
/// there and on gray; the other kinds are told apart from both.
constexpr std::array<Color, pcurv::LineKindCount> LineKindColors = { {
  { 1.00, 0.60, 0.00 },
  { 0.00, 0.70, 0.35 },
  { 0.90, 0.35, 0.75 },
  { 0.55, 0.35, 0.10 },
  { 0.55, 0.85, 0.95 },
  { 0.35, 0.20, 0.60 },
} };

/// An array of codes shown as categories: its name, its codes' names and
/// colors.
struct CategoricalArray
{
  const char* ArrayName;
  int Count;
  const char* (*Name)(int code);
  const Color* Colors;
};

const CategoricalArray CategoricalArrays[] = {
  { pcurv::ShapeClassArrayName,
    static_cast<int>(pcurv::ShapeClass::Count),
    [](int code) { return pcurv::ShapeClassName(static_cast<pcurv::ShapeClass>(code)); },
    ShapeClassColors.data() },
  { pcurv::LineKindArrayName,
    pcurv::LineKindCount,
    [](int code) { return pcurv::LineKindName(static_cast<pcurv::LineKind>(code)); },
    LineKindColors.data() },
};

/// The categorical array of that name, or null.
const CategoricalArray* CategoriesOf(const char* arrayName)
{
  for (const CategoricalArray& categories : CategoricalArrays)
  {
    if (arrayName && std::string(arrayName) == categories.ArrayName)
    {
      return &categories;
    }
  }
  return nullptr;
}

/// The map as categories: one color and one legend entry (its name) per
/// code of `codes`, whatever range the map had.
void MakeCategoricalMap(vtkSMProxy* map,
  const CategoricalArray& categories,
  const std::vector<int>& codes)
{
  std::vector<std::string> annotations;
  std::vector<double> colors;
  for (const int code : codes)
  {
    annotations.push_back(std::to_string(code));
    annotations.emplace_back(categories.Name(code));
    colors.insert(colors.end(), categories.Colors[code].begin(), categories.Colors[code].end());
  }
  // "Interpret Values As Categories" in the GUI and pvpython.
  vtkSMPropertyHelper(map, "IndexedLookup").Set(1);
  vtkSMPropertyHelper annotationsHelper(map, "Annotations");
  annotationsHelper.SetNumberOfElements(static_cast<unsigned int>(annotations.size()));
  for (unsigned int i = 0; i < annotations.size(); ++i)
  {
    annotationsHelper.Set(i, annotations[i].c_str());
  }
  vtkSMPropertyHelper(map, "IndexedColors")
    .Set(colors.data(), static_cast<unsigned int>(colors.size()));
  if (map->GetProperty("AnnotationsInitialized"))
  {
    // Keeps ParaView from replacing the names with the values it finds.
    vtkSMPropertyHelper(map, "AnnotationsInitialized").Set(1);
  }
  map->UpdateVTKObjects();
}

/// A new display of Curvature Lines: colored by the lines' kinds (its
/// cells), with lines wide enough to read over the cloud's points.
void ShowLinesByKind(vtkSMProxy* display)
{
  vtkSMPropertyHelper(display, "ColorArrayName")
    .SetInputArrayToProcess(vtkDataObject::FIELD_ASSOCIATION_CELLS, pcurv::LineKindArrayName);
  if (display->GetProperty("LineWidth"))
  {
    vtkSMPropertyHelper(display, "LineWidth").Set(3.0);
  }
  display->UpdateVTKObjects();
}

/// What the client knows of the field data array `name` of the display's
/// input, or null.
vtkPVArrayInformation* FieldArray(pqDataRepresentation* representation, const char* name)
{
  vtkPVDataInformation* data = representation->getInputDataInformation();
  return data ? data->GetFieldDataInformation()->GetArrayInformation(name) : nullptr;
}

/// The first string of the field data array `name`, or "".
std::string FieldText(pqDataRepresentation* representation, const char* name)
{
  vtkPVArrayInformation* array = FieldArray(representation, name);
  const char* text =
    array && array->GetNumberOfStringValues() > 0 ? array->GetStringValue(0) : nullptr;
  return text ? text : "";
}

/// The largest value of the numeric field data array `name`, or 0.
double FieldNumber(pqDataRepresentation* representation, const char* name)
{
  vtkPVArrayInformation* array = FieldArray(representation, name);
  return array && array->GetNumberOfComponents() > 0 ? array->GetComponentRange(0)[1] : 0.0;
}

/// Whether `map` is the map of the array `arrayName`. A display's map is
/// the array's only once both properties have changed (ParaView sets the
/// array, then the map): ParaView registers it under a name that ends with
/// the array's.
bool IsMapOf(vtkSMProxy* map, const std::string& arrayName)
{
  const char* mapName =
    map ? map->GetSessionProxyManager()->GetProxyName("lookup_tables", map) : nullptr;
  const std::string suffix = arrayName + ".PVLookupTable";
  const std::string registered = mapName ? mapName : "";
  return registered.size() >= suffix.size() &&
    registered.compare(registered.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// An output's name as a title: "Mean_Curvature" as "Mean curvature".
std::string Readable(const std::string& name)
{
  std::string text = name;
  for (std::size_t i = 1; i < text.size(); ++i)
  {
    const auto c = static_cast<unsigned char>(text[i]);
    text[i] = c == '_' ? ' ' : static_cast<char>(std::tolower(c));
  }
  return text;
}

/// The codes a legend of `categories` lists: every shape class; the line
/// kinds that were drawn (Line_Counts), all where that is not known.
std::vector<int> ShownCodes(pqDataRepresentation* representation,
  const CategoricalArray& categories)
{
  vtkPVArrayInformation* counts = categories.ArrayName == pcurv::LineKindArrayName
    ? FieldArray(representation, pcurv::LineCountsArrayName)
    : nullptr;
  std::vector<int> codes;
  for (int code = 0; code < categories.Count; ++code)
  {
    if (!counts || code >= counts->GetNumberOfComponents() ||
      counts->GetComponentRange(code)[1] > 0)
    {
      codes.push_back(code);
    }
  }
  return codes;
}

/// A display of one of the plugin's filters (curvatures, normals, lines).
bool ShowsCloudFilter(vtkSMProxy* display)
{
  vtkSMProxy* input = vtkSMPropertyHelper(display, "Input").GetAsProxy();
  return pcurv::IsCloudFilter(input) || pcurv::IsCurvatureLines(input);
}
} // namespace

namespace
{
/// The color map of another visible display of the plugin's filters in the
/// same view, colored by the same array: the map the new display shares.
vtkSMProxy* MapOfSameArrayInView(pqRepresentation* representation,
  const std::string& arrayName,
  int association)
{
  pqView* view = representation->getView();
  if (!view)
  {
    return nullptr;
  }
  for (pqRepresentation* other : view->getRepresentations())
  {
    vtkSMProxy* proxy = other ? other->getProxy() : nullptr;
    if (!proxy || other == representation || !other->isVisible() ||
      !proxy->GetProperty("LookupTable") || !proxy->GetProperty("Input") ||
      !ShowsCloudFilter(proxy))
    {
      continue;
    }
    vtkSMPropertyHelper colorArray(proxy, "ColorArrayName");
    const char* name = colorArray.GetInputArrayNameToProcess();
    if (name && arrayName == name && colorArray.GetInputArrayAssociation() == association)
    {
      return vtkSMPropertyHelper(proxy, "LookupTable").GetAsProxy();
    }
  }
  return nullptr;
}

/// Colors `display` with `map` (and its opacity function), and widens the
/// map to this display's range too.
void ShareMap(vtkSMProxy* display, vtkSMProxy* map)
{
  vtkSMPropertyHelper(display, "LookupTable").Set(map);
  if (display->GetProperty("ScalarOpacityFunction") && map->GetProperty("ScalarOpacityFunction"))
  {
    vtkSMPropertyHelper(display, "ScalarOpacityFunction")
      .Set(vtkSMPropertyHelper(map, "ScalarOpacityFunction").GetAsProxy());
  }
  display->UpdateVTKObjects();
  vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(
    display, /*extend=*/true, /*force=*/true);
}
} // namespace

pqCloudColorMapBehavior::pqCloudColorMapBehavior(QObject* parent)
  : QObject(parent)
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(
    model, &pqServerManagerModel::viewAdded, this, &pqCloudColorMapBehavior::watchView);
  // The GUI's first view exists before the plugin is loaded.
  for (pqView* view : model->findItems<pqView*>())
  {
    this->watchView(view);
  }
}

void pqCloudColorMapBehavior::watchView(pqView* view)
{
  // A view reports a display once it is added to it, which ParaView does
  // after it has given the display the shared color map of its array.
  QObject::connect(
    view, &pqView::representationAdded, this, &pqCloudColorMapBehavior::giveOwnColorMap);
  QObject::connect(
    view, &pqView::representationAdded, this, &pqCloudColorMapBehavior::watchColorBar);
}

void pqCloudColorMapBehavior::watchColorBar(pqRepresentation* representation)
{
  auto* data = qobject_cast<pqDataRepresentation*>(representation);
  if (!data || !data->getProxy()->GetProperty("LookupTable") ||
    pqApplicationCore::instance()->isLoadingState())
  {
    return;
  }
  // ParaView sets the array, then the map: described after each.
  QObject::connect(data,
    &pqDataRepresentation::colorArrayNameModified,
    this,
    [data]() { pqCloudColorMapBehavior::describeColorBar(data); });
  QObject::connect(data,
    &pqDataRepresentation::colorTransferFunctionModified,
    this,
    [data]() { pqCloudColorMapBehavior::describeColorBar(data); });
  pqCloudColorMapBehavior::describeColorBar(data);
}

void pqCloudColorMapBehavior::describeColorBar(pqDataRepresentation* representation)
{
  vtkSMProxy* display = representation->getProxy();
  pqView* view = representation->getView();
  const char* arrayName =
    vtkSMPropertyHelper(display, "ColorArrayName", /*quiet=*/true).GetInputArrayNameToProcess();
  const pcurv::OutputArray* row = arrayName ? pcurv::FindOutput(arrayName) : nullptr;
  vtkSMProxy* map = vtkSMPropertyHelper(display, "LookupTable").GetAsProxy();
  // Only a curvature filter's output (saved or not) says its unit.
  if (!row || !view || CategoriesOf(arrayName) || !IsMapOf(map, arrayName) ||
    FieldText(representation, "Curvature_Unit").empty())
  {
    return;
  }
  // The bar is made now if it does not exist yet, hidden: ParaView shows
  // this one when it shows the map's bar (after an Apply, or asked to).
  vtkSMProxy* bar = vtkSMTransferFunctionProxy::FindScalarBarRepresentation(map, view->getProxy());
  const bool made = bar == nullptr;
  if (made)
  {
    vtkNew<vtkSMTransferFunctionManager> manager;
    bar = manager->GetScalarBarRepresentation(map, view->getProxy());
  }
  if (!bar || !bar->GetProperty("Title"))
  {
    return;
  }
  if (made && bar->GetProperty("Visibility"))
  {
    vtkSMPropertyHelper(bar, "Visibility").Set(0);
  }
  const std::string unit = pcurv::UnitText(row->Unit, FieldText(representation, "Length_Unit"));
  const std::string title = Readable(row->Name) + (unit.empty() ? "" : " (" + unit + ")");
  vtkSMPropertyHelper(bar, "Title").Set(title.c_str());
  if (row->Components == 1 && bar->GetProperty("ComponentTitle"))
  {
    // Left from an earlier array of several components (RGB's): one
    // component has no component to name.
    vtkSMPropertyHelper(bar, "ComponentTitle").Set("");
  }
  const double unestimated = FieldNumber(representation, "Unestimated_Points");
  if (row->Value == pcurv::OutputValue::Real && unestimated > 0 &&
    bar->GetProperty("DrawNanAnnotation"))
  {
    // The points in the map's NaN color, named and counted.
    const std::string nan =
      "not estimated (" + std::to_string(static_cast<long long>(unestimated)) + ")";
    vtkSMPropertyHelper(bar, "DrawNanAnnotation").Set(1);
    vtkSMPropertyHelper(bar, "NanAnnotation").Set(nan.c_str());
  }
  bar->UpdateVTKObjects();
  representation->renderViewEventually();
}

void pqCloudColorMapBehavior::giveOwnColorMap(pqRepresentation* representation)
{
  vtkSMProxy* display = representation ? representation->getProxy() : nullptr;
  if (!display || !display->GetProperty("UseSeparateColorMap") || !display->GetProperty("Input") ||
    pqApplicationCore::instance()->isLoadingState())
  {
    return;
  }
  if (!ShowsCloudFilter(display))
  {
    return;
  }
  vtkSMPropertyHelper(display, "UseSeparateColorMap").Set(1);
  if (pcurv::IsCurvatureLines(vtkSMPropertyHelper(display, "Input").GetAsProxy()))
  {
    auto* data = qobject_cast<pqDataRepresentation*>(representation);
    vtkPVDataInformation* info = data ? data->getInputDataInformation() : nullptr;
    if (info && info->GetNumberOfCells() == 0)
    {
      // No line drawn: no colors and no legend (the filter's warning says
      // why), rather than a map of an empty array.
      vtkSMPVRepresentationProxy::SetScalarColoring(display, nullptr, 0);
      display->UpdateVTKObjects();
      return;
    }
    ShowLinesByKind(display);
  }
  // The display is already colored (by the output's active scalars) with
  // the shared map: coloring again picks the display's own map, which is
  // then scaled to this output alone.
  vtkSMPropertyHelper colorArray(display, "ColorArrayName");
  const std::string arrayName =
    colorArray.GetInputArrayNameToProcess() ? colorArray.GetInputArrayNameToProcess() : "";
  const int association = colorArray.GetInputArrayAssociation();
  if (vtkSMProxy* shared =
        arrayName.empty() ? nullptr : MapOfSameArrayInView(representation, arrayName, association))
  {
    ShareMap(display, shared);
  }
  else if (!arrayName.empty())
  {
    vtkSMPVRepresentationProxy::SetScalarColoring(
      display, arrayName.c_str(), colorArray.GetInputArrayAssociation());
    vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(
      display, /*extend=*/false, /*force=*/true);
  }
  display->UpdateVTKObjects();
  // Whenever the display is colored by the shape classes or the line
  // kinds (and again when its map changes: ParaView sets the array, then
  // the map), categories; the lines are colored by their kinds already.
  if (auto* data = qobject_cast<pqDataRepresentation*>(representation))
  {
    QObject::connect(data,
      &pqDataRepresentation::colorArrayNameModified,
      this,
      [data]() { pqCloudColorMapBehavior::colorCategories(data); });
    QObject::connect(data,
      &pqDataRepresentation::colorTransferFunctionModified,
      this,
      [data]() { pqCloudColorMapBehavior::colorCategories(data); });
    pqCloudColorMapBehavior::colorCategories(data);
  }
}

void pqCloudColorMapBehavior::colorCategories(pqDataRepresentation* representation)
{
  vtkSMProxy* display = representation->getProxy();
  vtkSMPropertyHelper colorArray(display, "ColorArrayName", /*quiet=*/true);
  const char* arrayName = colorArray.GetInputArrayNameToProcess();
  vtkSMProxy* map = display->GetProperty("LookupTable")
    ? vtkSMPropertyHelper(display, "LookupTable").GetAsProxy()
    : nullptr;
  const CategoricalArray* categories = CategoriesOf(arrayName);
  if (!categories || !IsMapOf(map, categories->ArrayName) ||
    vtkSMPropertyHelper(map, "IndexedLookup").GetAsInt() == 1)
  {
    return;
  }
  MakeCategoricalMap(map, *categories, ShownCodes(representation, *categories));
  // The legend: the names by their colors.
  if (pqView* view = representation->getView())
  {
    vtkSMPVRepresentationProxy::SetScalarBarVisibility(display, view->getProxy(), true);
  }
  representation->renderViewEventually();
}
