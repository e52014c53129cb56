/**
 * @class pqCloudColorMapBehavior
 * @brief Gives the displays of this plugin's filters one color map per
 * view and array, scaled to the outputs shown there when each is first
 * shown.
 *
 * ParaView keeps one color map per array name, and its default rescale
 * mode only grows that map's range at each Apply: a second cloud colored
 * by the same array (Mean_Curvature_Clipped) kept the first one's range and
 * showed in one color when its curvatures were a hundredth of the first's.
 * Setting the map's mode to "Update on 'Apply'" is not enough: the range
 * then spans every visible display using the map, the first cloud's too.
 * A separate color map per display (ParaView's "Use Separate Color Map")
 * gives each cloud its own range, and leaves the others' colors as they
 * were. In one view, though, two maps of one array would show two color
 * bars with the same title and different ranges, and one color meaning
 * two values: a display added to a view where another of the plugin's
 * displays is colored by the same array shares that display's map (one
 * color bar), whose range is widened to cover both. Clouds in separate
 * views keep separate maps. Not applied while a state file loads: its
 * color maps are kept.
 *
 * Colored by one of the curvature filter's output arrays (of its output,
 * or of a saved result read back: any data with Curvature_Unit field
 * data), the color bar's title is the array's name in words with its unit
 * from the output table (Estimation/OutputTable.h) and the data's
 * Length_Unit: "Mean curvature (1/foot)". Where points were not
 * estimated, the bar shows the map's NaN color as "not estimated (N)".
 *
 * Colored by Shape_Class or Line_Kind, a display's map is categorical: a
 * color and a legend entry named after each class (pcurv::ShapeClass) or
 * line kind (pcurv::LineKind), shown; the line kinds listed are those
 * drawn (the field data Line_Counts). A display of Curvature Lines is
 * colored by Line_Kind when it is first shown, its lines 3 pixels wide;
 * one with no line is left uncolored, with no legend.
 */
#ifndef pqCloudColorMapBehavior_h
#define pqCloudColorMapBehavior_h

#include <QObject>

class pqDataRepresentation;
class pqRepresentation;
class pqView;

class pqCloudColorMapBehavior : public QObject
{
  Q_OBJECT
public:
  explicit pqCloudColorMapBehavior(QObject* parent = nullptr);

private Q_SLOTS:
  void watchView(pqView* view);
  /// A new display of one of the plugin's filters: the view's map of its
  /// array, else its own.
  void giveOwnColorMap(pqRepresentation* representation);
  /// Any new display: its color bar described while it is colored by an
  /// output array (describeColorBar).
  void watchColorBar(pqRepresentation* representation);

private:
  /// Colored by Shape_Class or Line_Kind: its map as categories with
  /// their names.
  static void colorCategories(pqDataRepresentation* representation);
  /// The color bar's title (name and unit) and NaN annotation.
  static void describeColorBar(pqDataRepresentation* representation);
};

#endif
