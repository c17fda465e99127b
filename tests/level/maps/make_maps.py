#!/usr/bin/env python3
# Writes the test maps of this directory (tests/level/test_tiled.cpp says what they hold):
# the same 8 x 4 level as Tiled's JSON with the layer's data plain, base64, zlib and gzip,
# with its tileset external (tiles.tsj), and as TMX with CSV data. Run it here to make
# them again: python3 make_maps.py
import base64, gzip, json, struct, zlib

W, H = 8, 4
gids = [0] * 8 + [0, 0, 2, 2, 0, 0, 0, 6] + [0, 0, 0, 0, 0, 3, 4, 5] + [1] * 8
tileset = {"name": "tiles", "tilewidth": 16, "tileheight": 16, "tilecount": 8, "columns": 4,
           "image": "tiles.png", "imagewidth": 64, "imageheight": 32, "margin": 0, "spacing": 0,
           "tiles": [
               {"id": 0, "properties": [{"name": "collision", "type": "string", "value": "solid"}]},
               {"id": 1, "properties": [{"name": "collision", "type": "string", "value": "oneWay"}]},
               {"id": 2, "properties": [{"name": "collision", "type": "string", "value": "/"}]},
               {"id": 3, "objectgroup": {"draworder": "index", "name": "", "objects": [
                   {"id": 1, "name": "", "type": "", "x": 0, "y": 0, "width": 16, "height": 16,
                    "rotation": 0, "visible": True}],
                   "opacity": 1, "type": "objectgroup", "visible": True, "x": 0, "y": 0}},
               {"id": 4, "objectgroup": {"draworder": "index", "name": "", "objects": [
                   {"id": 1, "name": "", "type": "", "x": 0, "y": 0, "width": 0, "height": 0,
                    "rotation": 0, "visible": True,
                    "polygon": [{"x": 16, "y": 0}, {"x": 16, "y": 16}, {"x": 0, "y": 16}]}],
                   "opacity": 1, "type": "objectgroup", "visible": True, "x": 0, "y": 0}}]}


def obj(i, name, cls, x, y, w, h, props=None, **kw):
    o = {"id": i, "name": name, "type": cls, "x": x, "y": y, "width": w, "height": h, "rotation": 0,
         "visible": True}
    if props:
        o["properties"] = [{"name": k, "type": t, "value": v} for k, t, v in props]
    o.update(kw)
    return o


objects = [
    obj(1, "crate", "", 32, 0, 16, 16, [("type", "string", "dynamic"), ("friction", "float", 0.25)]),
    obj(2, "spawn", "", 8, 40, 0, 0, None, point=True),
    obj(3, "lift", "platform", 96, 32, 32, 8, [("type", "string", "kinematic")]),
    obj(4, "ball", "", 0, 0, 16, 16, [("type", "string", "dynamic"), ("bounce", "float", 0.5)], ellipse=True),
    obj(5, "zone", "", 64, 0, 32, 16, [("body", "bool", False), ("coins", "int", 3), ("label", "string", "bonus")]),
    obj(6, "coin", "pickup", 112, 40, 8, 8, [("type", "string", "static"), ("sensor", "bool", True)]),
]


def map_json(layer_data):
    return {"compressionlevel": -1, "height": H, "width": W, "infinite": False, "orientation": "orthogonal",
            "renderorder": "right-down", "tiledversion": "1.8.2", "tilewidth": 16, "tileheight": 16,
            "type": "map", "version": "1.8", "nextlayerid": 3, "nextobjectid": 7,
            "properties": [{"name": "gravityY", "type": "float", "value": 800}],
            "tilesets": [dict(firstgid=1, **tileset)],
            "layers": [dict({"id": 1, "name": "ground", "type": "tilelayer", "x": 0, "y": 0, "width": W,
                             "height": H, "opacity": 1, "visible": True}, **layer_data),
                       {"id": 2, "name": "things", "type": "objectgroup", "draworder": "topdown", "x": 0, "y": 0,
                        "opacity": 1, "visible": True, "objects": objects}]}


def write_json(name, value):
    with open(name, "w") as f:
        json.dump(value, f, indent=1)


packed = struct.pack("<%dI" % len(gids), *gids)
write_json("level.tmj", map_json({"data": gids}))
write_json("level_base64.tmj", map_json({"encoding": "base64", "data": base64.b64encode(packed).decode()}))
write_json("level_zlib.tmj", map_json({"encoding": "base64", "compression": "zlib",
                                        "data": base64.b64encode(zlib.compress(packed)).decode()}))
write_json("level_gzip.tmj", map_json({"encoding": "base64", "compression": "gzip",
                                        "data": base64.b64encode(gzip.compress(packed, mtime=0)).decode()}))
external = map_json({"data": gids})
external["tilesets"] = [{"firstgid": 1, "source": "tiles.tsj"}]
write_json("level_external.tmj", external)
write_json("tiles.tsj", dict(tileset, type="tileset", version="1.8", tiledversion="1.8.2"))


def properties_xml(props, indent):
    if not props:
        return ""
    out = indent + "<properties>\n"
    for k, t, v in props:
        value = ("true" if v else "false") if t == "bool" else v
        kind = "" if t == "string" else ' type="%s"' % t
        out += indent + ' <property name="%s"%s value="%s"/>\n' % (k, kind, value)
    return out + indent + "</properties>\n"


x = '<?xml version="1.0" encoding="UTF-8"?>\n'
x += ('<map version="1.8" tiledversion="1.8.2" orientation="orthogonal" renderorder="right-down" '
      'width="8" height="4" tilewidth="16" tileheight="16" infinite="0" nextlayerid="3" nextobjectid="7">\n')
x += ' <properties>\n  <property name="gravityY" type="float" value="800"/>\n </properties>\n'
x += ' <tileset firstgid="1" name="tiles" tilewidth="16" tileheight="16" tilecount="8" columns="4">\n'
x += '  <image source="tiles.png" width="64" height="32"/>\n'
for tile_id, value in ((0, "solid"), (1, "oneWay"), (2, "/")):
    x += '  <tile id="%d">\n   <properties>\n    <property name="collision" value="%s"/>\n' % (tile_id, value)
    x += '   </properties>\n  </tile>\n'
x += '  <tile id="3">\n   <objectgroup draworder="index" id="2">\n'
x += '    <object id="1" x="0" y="0" width="16" height="16"/>\n   </objectgroup>\n  </tile>\n'
x += '  <tile id="4">\n   <objectgroup draworder="index" id="2">\n    <object id="1" x="0" y="0">\n'
x += '     <polygon points="16,0 16,16 0,16"/>\n    </object>\n   </objectgroup>\n  </tile>\n'
x += ' </tileset>\n <layer id="1" name="ground" width="8" height="4">\n  <data encoding="csv">\n'
x += ",\n".join(",".join(str(g) for g in gids[r * W:(r + 1) * W]) for r in range(H)) + "\n</data>\n </layer>\n"
x += ' <objectgroup id="2" name="things">\n'
for o in objects:
    attrs = 'id="%d"' % o["id"]
    if o["name"]:
        attrs += ' name="%s"' % o["name"]
    if o["type"]:
        attrs += ' type="%s"' % o["type"]
    attrs += ' x="%g" y="%g"' % (o["x"], o["y"])
    if o["width"] or o["height"]:
        attrs += ' width="%g" height="%g"' % (o["width"], o["height"])
    inner = properties_xml([(p["name"], p["type"], p["value"]) for p in o.get("properties", [])], "   ")
    if o.get("ellipse"):
        inner += "   <ellipse/>\n"
    if o.get("point"):
        inner += "   <point/>\n"
    x += ('  <object %s>\n%s  </object>\n' % (attrs, inner)) if inner else '  <object %s/>\n' % attrs
x += ' </objectgroup>\n</map>\n'
with open("level.tmx", "w") as f:
    f.write(x)
