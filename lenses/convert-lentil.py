#!/usr/bin/env python3
"""Convert designs from lentil's lens database (lentil-lenses.json, by Zeno
Pelgrims) into lensrt's JSON lens format. Kept so the library files can be
regenerated and checked: python3 convert-lentil.py /path/to/lentil-lenses.json"""
import json
import sys

# lentil id -> (our name, description)
PICKS = {
    "0001": ("angenieux-dgauss-100mm", "Angenieux double Gauss F/1.1, six elements"),
    "0002": ("primoplan-100mm", "Meyer-Optik Goerlitz Primoplan F/1.5 (Paul Schaefter)"),
    "0004": ("nikon-retrofocus-100mm", "Nikon retrofocus wide angle"),
    "0006": ("petzval-100mm", "Kodak Petzval portrait lens"),
    "0009": ("biotar-100mm", "Zeiss Biotar double Gauss"),
    "0010": ("takumar-100mm", "Asahi (Pentax) Takumar 50 mm design at 100 mm"),
}
# Clear apertures (diameter, mm) reduced where lentil's housing radii would make
# neighbouring surfaces intersect: id -> {surface index (0-based): diameter}.
APERTURE_FIXES = {
    "0004": {10: 48.6, 11: 48.6},  # 2.52 mm air gap between R 188.11 and R -323.43
    "0009": {4: 44.9, 5: 44.9},    # the stop plane meets the R 28.3 surface at 22.47 mm
}
FLAT = 9e4  # lentil writes 99999 or 100000 for a plane surface


def convert(lens_id, entry, name, description):
    surfaces = []
    fixes = APERTURE_FIXES.get(lens_id, {})
    for i, e in enumerate(entry["optical-elements-patent"]):
        stop = e["material"].lower() == "iris"
        radius = 0.0 if stop or abs(e["radius"]) >= FLAT else round(e["radius"], 4)
        s = {"radius": radius, "thickness": round(e["thickness"], 4), "aperture": fixes.get(i, round(2 * e["housing-radius"], 4))}
        if e["ior"] not in (None, 1.0) and not stop:
            s["nd"] = round(e["ior"], 6)
            if e["abbe"]:
                s["vd"] = round(e["abbe"], 4)
            if e["material"] not in ("abbe", "air"):
                s["glass"] = e["material"]
        if stop:
            s["stop"] = True
        surfaces.append(s)
    source = f"{entry['company']} {entry['product-name']} ({entry['year']})"
    if entry.get("patent-number"):
        source += f", patent {entry['patent-number']}"
    source += f"; retyped from lentil-lenses.json (lentil by Zeno Pelgrims), id {lens_id}"
    if fixes:
        source += ("; clear apertures of surfaces " + ", ".join(str(i + 1) for i in fixes) +
                   " reduced so neighbouring surfaces do not intersect")
    return {"format": "lensrt-lens", "version": 1, "name": name, "description": description, "source": source,
            "focal_length_mm": float(entry["focal-length-mm-patent"]), "surfaces": surfaces}


def main():
    db = json.load(open(sys.argv[1]))
    for lens_id, (name, description) in PICKS.items():
        doc = convert(lens_id, db[lens_id], name, description)
        with open(f"{name}.json", "w") as f:
            f.write("{\n")
            keys = [k for k in doc if k != "surfaces"]
            for k in keys:
                f.write(f"  {json.dumps(k)}: {json.dumps(doc[k])},\n")
            f.write('  "surfaces": [\n')
            f.write(",\n".join("    " + json.dumps(s) for s in doc["surfaces"]))
            f.write("\n  ]\n}\n")


if __name__ == "__main__":
    main()
