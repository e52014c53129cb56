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
- render_principal_directions.py defaults to the filter's fit and takes every
  fit mode; no document calls another fit the default.

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

# The default fit as the tools and the documentation state it.
import os
import re

fit_names = {int(e.get("value")): e.get("text")
             for p in proxy if p.get("name") == "FitMode" for e in p.iter("Entry")}
default_fit = fit_names[vtkPrincipalCurvatureEstimation().GetFitMode()]
render_path = os.path.join(os.path.dirname(cli_path), "render_principal_directions.py")
spec = importlib.util.spec_from_file_location("render_principal_directions", render_path)
render = importlib.util.module_from_spec(spec)
spec.loader.exec_module(render)
rendered = render.parse_arguments(["in.vtp", "out.png"])
check(rendered.fit_mode == default_fit, "render_principal_directions.py: default --fit-mode %s (the filter's %s)"
      % (rendered.fit_mode, default_fit))
check(sorted(render.parse_arguments(["a", "b", "--fit-mode", name]).fit_mode for name in fit_names.values())
      == sorted(fit_names.values()), "render_principal_directions.py: --fit-mode takes %s"
      % " ".join(sorted(fit_names.values())))
# Stale claims that another fit is the default ("Default fit mode New01",
# "SetFitModeToNew01(); // the default", "New01 (the default)").
repository = os.path.dirname(os.path.dirname(os.path.abspath(cli_path)))
documents = [os.path.join(repository, "README.md")] + [
    os.path.join(repository, "docs", name) for name in sorted(os.listdir(os.path.join(repository, "docs")))
    if name.endswith(".md")]
for name in (n for n in fit_names.values() if n != default_fit):
    claim = re.compile(r"default fit mode:?\s+\**%s\b|%s\b[^.]*\bthe default\b" % (name, name), re.IGNORECASE)
    stale = ["%s:%d" % (os.path.relpath(path, repository), number)
             for path in documents for number, line in enumerate(open(path), 1) if claim.search(line)]
    check(not stale, "no document calls %s the default (%s)" % (name, " ".join(stale) or "none"))

print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
