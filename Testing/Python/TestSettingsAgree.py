"""The settings are defined once, in the numeric core (pcurv::EstimationSettings,
pcurv::AdjustmentConstants), and read by the filter; the places that cannot
include C++ are checked against it here:

- every default_values of the plugin XML equals the filter's default;
- the XML's enumerations equal the filter's enum constants;
- the XML's ranges (the panel's sliders) start at the filter's clamp minimum
  and end within its clamp maximum (a slider spans typical values; a typed
  larger one is kept and clamped by the filter);
- the command-line tool's --dynamic-adjustment table equals the presets;
- the XML's documentation quotes the banded ladder's switch lengths.

    pvpython TestSettingsAgree.py PLUGIN.xml estimate_curvatures.py
(with the wrapped package on PYTHONPATH)
"""

import importlib.util
import sys
import xml.etree.ElementTree as ElementTree

from principal_curvatures import vtkPrincipalCurvatureEstimation

xml_path, cli_path = sys.argv[1], sys.argv[2]
failures = []


def check(condition, message):
    print(("ok      " if condition else "FAILED  ") + message)
    if not condition:
        failures.append(message)


def values(text, kind):
    return [kind(v) for v in text.split()]


import principal_curvatures

checked = 0
for proxy in ElementTree.parse(xml_path).iter("SourceProxy"):
    cls = getattr(principal_curvatures, proxy.get("class"), None)
    if cls is None:
        continue
    defaults = cls()
    for prop in proxy:
        command = prop.get("command") or ""
        if not command.startswith("Set") or prop.get("default_values") is None:
            continue
        getter = getattr(defaults, "Get" + command[3:], None)
        if getter is None:
            continue
        kind = float if prop.tag == "DoubleVectorProperty" else int
        expected = getter()
        expected = list(expected) if isinstance(expected, tuple) else [expected]
        given = values(prop.get("default_values"), kind)
        check([kind(v) for v in expected] == given, "%s.%s: XML default %s, filter default %s" % (
            proxy.get("name"), prop.get("name"), given, expected))
        checked += 1
        for domain in prop:
            if domain.tag in ("IntRangeDomain", "DoubleRangeDomain"):
                for end in ("min", "max"):
                    clamp = getattr(defaults, "Get%s%sValue" % (command[3:], end.capitalize()), None)
                    if domain.get(end) is not None and clamp is not None:
                        given, limit = kind(domain.get(end)), kind(clamp())
                        check(given == limit if end == "min" else given <= limit,
                              "%s.%s: XML %s %s, clamp %s" % (
                                  proxy.get("name"), prop.get("name"), end, domain.get(end), clamp()))
check(checked >= 25, "%d XML defaults compared" % checked)

filter_defaults = vtkPrincipalCurvatureEstimation()
proxy = next(p for p in ElementTree.parse(xml_path).iter("SourceProxy")
             if p.get("class") == "vtkPrincipalCurvatureEstimation")
enumerations = {
    "FitMode": {"Previous": filter_defaults.PREVIOUS, "New01": filter_defaults.NEW01,
                "New02": filter_defaults.NEW02, "OrientedCircles": filter_defaults.ORIENTED_CIRCLES},
    "NeighborhoodMode": {"Radius": filter_defaults.RADIUS, "K Nearest": filter_defaults.K_NEAREST,
                         "Automatic": filter_defaults.AUTOMATIC_SCALE},
    "NormalsSource": {"Automatic": filter_defaults.AUTOMATIC_NORMALS,
                      "Input Array": filter_defaults.INPUT_NORMALS,
                      "Estimated": filter_defaults.ESTIMATED_NORMALS},
    "NormalOrientation": {"Outward": filter_defaults.OUTWARD,
                          "Towards Viewpoint": filter_defaults.TOWARDS_VIEWPOINT,
                          "Along Axis": filter_defaults.ALONG_AXIS},
}
for prop in proxy:
    if prop.get("name") in enumerations:
        entries = {e.get("text"): int(e.get("value")) for e in prop.iter("Entry")}
        check(entries == enumerations[prop.get("name")],
              "%s: XML entries %s" % (prop.get("name"), entries))

spec = importlib.util.spec_from_file_location("estimate_curvatures", cli_path)
cli = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cli)
presets = {"paper": filter_defaults.PAPER_CONSTANTS, "ladder": filter_defaults.LADDER,
           "noisy-ladder": filter_defaults.NOISY_LADDER}
check(sorted(cli.ADJUSTMENTS) == sorted(presets), "the tool's adjustment names: %s" % sorted(cli.ADJUSTMENTS))
for name, preset in presets.items():
    f = vtkPrincipalCurvatureEstimation()
    f.SetAdjustmentConstantsToPreset(preset)
    for setting, given in cli.ADJUSTMENTS.get(name, {}).items():
        expected = list(getattr(f, "Get" + setting)())
        check([float(v) for v in given] == expected,
              "--dynamic-adjustment %s: %s %s, filter preset %s" % (name, setting, given, expected))

ladder = vtkPrincipalCurvatureEstimation()
ladder.SetAdjustmentConstantsToPreset(ladder.LADDER)
switches = " ".join("%g" % v for v in ladder.GetSwitchLengths())
documentation = " ".join(" ".join(d.text.split()) for d in proxy.iter("Documentation") if d.text)
check(switches in documentation, "the XML documentation quotes the ladder's switch lengths %s" % switches)

print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
