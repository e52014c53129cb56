/**
 * @class pqCloudReaderDisplayBehavior
 * @brief How a display of one of this plugin's readers starts in ParaView's
 * GUI: in the cloud's true colors, and in view.
 *
 * - True colors. The readers make a scan's colors the active scalars, an
 *   8-bit RGB array (the LAS reader derives it from the 16-bit Red, Green
 *   and Blue): ParaView colors the first display by it, but through a color
 *   map of the colors' magnitude. For a display colored by 3 or 4
 *   unsigned-char components this turns Map Scalars off, so that the points
 *   show their own colors (the Properties panel's "Map Scalars" box,
 *   unchecked), and hides the scalar bar, which would describe a map that
 *   is not used. It stays so only while the display is colored by such
 *   colors: colored by any other array (a classification, a curvature), Map
 *   Scalars is turned back on, so that the array goes through its color map
 *   instead of being drawn as gray levels or black. Colors that are the
 *   same at every point (Red, Green and Blue fields never filled) are not
 *   chosen: the display starts in a solid color.
 * - In view. ParaView resets the camera only when the first cloud goes into
 *   an empty view: a second georeferenced tile a few kilometers away then
 *   lands off-screen. When a new display's bounds are not wholly inside the
 *   view, the camera is reset to everything visible. A cloud already in view
 *   leaves the camera where the user put it.
 *
 * Displays made while a state file loads are left as the state says.
 */
#ifndef pqCloudReaderDisplayBehavior_h
#define pqCloudReaderDisplayBehavior_h

#include <QObject>

class pqRepresentation;
class pqView;

class pqCloudReaderDisplayBehavior : public QObject
{
  Q_OBJECT
public:
  explicit pqCloudReaderDisplayBehavior(QObject* parent = nullptr);

private Q_SLOTS:
  void watchView(pqView* view);
  void startDisplay(pqRepresentation* representation);
};

#endif
