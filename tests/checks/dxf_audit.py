#!/usr/bin/env python3
"""A DXF sheet as another CAD reader sees it: ezdxf (Debian's python3-ezdxf) reads it, audits it
with no error and no fix, and finds millimetres ($INSUNITS 4), the view labels and the scale
caption as TEXT, and the strokes as LWPOLYLINEs on the layers the writer names.

usage: dxf_audit.py FILE.dxf LABEL...
"""
import sys

import ezdxf


def main():
    path, labels = sys.argv[1], sys.argv[2:]
    doc = ezdxf.readfile(path)
    audit = doc.audit()
    problems = [e.message for e in audit.errors] + [f.message for f in audit.fixes]
    assert not problems, "ezdxf's audit: " + "; ".join(problems)
    assert doc.header["$INSUNITS"] == 4, "units: %r" % doc.header["$INSUNITS"]
    texts = [t.dxf.text for t in doc.modelspace().query("TEXT")]
    for want in labels:
        assert want in texts, "no TEXT %r in %r" % (want, texts)
    strokes = doc.modelspace().query("LWPOLYLINE")
    assert len(strokes) > 0, "no strokes"
    layers = {s.dxf.layer for s in strokes}
    assert all(doc.layers.has_entry(n) for n in layers), layers
    print("dxf audit: clean, %d strokes on %d layers, texts %s" % (len(strokes), len(layers), texts))


if __name__ == "__main__":
    main()
