"""What stepFmus.py needs of an FMU's modelDescription.xml (FMI 2.0 or
3.0): its version, modelIdentifier, GUID or instantiationToken and its Real
(Float64) variables, a 3.0 array taken apart into elements under FMI 2.0's
names.
"""
import os
import xml.etree.ElementTree as ET

from fmucalls import Failure


def element_names(name, dimensions):
    """FMI 2.0's names of the elements of a 3.0 array, row-major."""
    names = [name]
    for n in dimensions:
        names = [f"{base}{',' if '[' in base else '['}{i}" for base in names
                 for i in range(1, n + 1)]
    return [n + "]" for n in names] if dimensions else names


class Description:
    """What a run needs of modelDescription.xml: version ("2" or "3"),
    identifier, token (GUID or instantiationToken), sizes {valueReference:
    elements of its array (1 for a scalar)} and elements {2.0 name:
    (valueReference, causality, start, offset in its array)} of the Real
    (Float64) variables."""

    def __init__(self, folder):
        root = ET.parse(os.path.join(folder, "modelDescription.xml")).getroot()
        self.version = root.get("fmiVersion", "")[:1]
        if self.version not in ("2", "3"):
            raise Failure(f"fmiVersion {root.get('fmiVersion')!r}: neither 2.0 nor 3.0")
        cs = root.find("CoSimulation")
        if cs is None:
            raise Failure("no <CoSimulation> in modelDescription.xml")
        self.identifier = cs.get("modelIdentifier")
        self.token = root.get("guid" if self.version == "2" else "instantiationToken")
        self.sizes, self.elements = {}, {}
        variables = root.find("ModelVariables")
        if self.version == "2":
            for v in variables:
                real = v.find("Real")
                if real is not None:
                    self.add(v.get("name"), [], v.get("valueReference"), v.get("causality"),
                             real.get("start"))
            return
        structural = {v.get("valueReference"): v.get("start") for v in variables}
        for v in variables:
            if v.tag != "Float64":
                continue
            dimensions = []
            for d in v.findall("Dimension"):
                start = d.get("start") or structural.get(d.get("valueReference"))
                if start is None:
                    raise Failure(f"{v.get('name')}: a Dimension without start or a known "
                                  f"structural parameter (valueReference {d.get('valueReference')})")
                dimensions.append(int(start))
            self.add(v.get("name"), dimensions, v.get("valueReference"), v.get("causality"),
                     v.get("start"))

    def add(self, name, dimensions, reference, causality, start):
        names = element_names(name, dimensions)
        starts = [None] * len(names) if start is None else [float(x) for x in start.split()]
        if len(starts) != len(names):
            raise Failure(f"{name}: {len(starts)} start values for {len(names)} elements")
        reference = int(reference)
        self.sizes[reference] = len(names)
        for offset, (element, value) in enumerate(zip(names, starts)):
            self.elements[element] = (reference, causality, value, offset)
