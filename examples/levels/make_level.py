#!/usr/bin/env python3
# Writes the example level of docs/levels.md: tiles.png (the tileset's picture), tiles.tsx
# (the tileset: which tile collides how) and level.tmx, as Tiled saves them. level.tmj is
# Tiled's own export of level.tmx, its tileset embedded so that the one file is the whole
# level (tiled --embed-tilesets --export-map json level.tmx level.tmj); the tests check
# that both give the same level. Open level.tmx in Tiled to draw it further.
import struct, zlib

TILE = 16
COLUMNS, ROWS = 40, 15

# --- tiles.png: 4 x 2 tiles of 16 px, each drawn plainly -------------------------------
def png(width, height, pixel):
    raw = b"".join(b"\x00" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

def tile_pixel(x, y):
    tile, u, v = (y // TILE) * 4 + x // TILE, x % TILE, y % TILE
    clear = (0, 0, 0, 0)
    if tile == 0:  # solid: brown earth with a darker border
        return (110, 78, 52, 255) if 0 < u < 15 and 0 < v < 15 else (70, 48, 32, 255)
    if tile == 1:  # one-way: a plank along the top
        return (160, 120, 70, 255) if v < 5 else clear
    if tile == 2:  # ramp rising to the right: the bottom-right half
        return (110, 78, 52, 255) if u + v >= 15 else clear
    if tile == 3:  # grass, decoration
        return (70, 160, 60, 255) if v > 10 and (u * 7 + v * 3) % 5 < 3 else clear
    return clear

with open("tiles.png", "wb") as f:
    f.write(png(4 * TILE, 2 * TILE, tile_pixel))

# --- tiles.tsx --------------------------------------------------------------------------
with open("tiles.tsx", "w") as f:
    f.write('''<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="tiles" tilewidth="16" tileheight="16" tilecount="8" columns="4">
 <image source="tiles.png" width="64" height="32"/>
 <tile id="0">
  <properties>
   <property name="collision" value="solid"/>
  </properties>
 </tile>
 <tile id="1">
  <properties>
   <property name="collision" value="oneWay"/>
  </properties>
 </tile>
 <tile id="2">
  <objectgroup draworder="index" id="2">
   <object id="1" x="0" y="0">
    <polygon points="16,0 16,16 0,16"/>
   </object>
  </objectgroup>
 </tile>
</tileset>
''')

# --- level.tmx ---------------------------------------------------------------------------
SOLID, ONE_WAY, RAMP, GRASS = 1, 2, 3, 4    # global ids (first gid 1)
FLIP_H = 0x80000000
cells = [[0] * COLUMNS for _ in range(ROWS)]
for c in range(COLUMNS):
    cells[ROWS - 1][c] = SOLID                 # the floor
for r in range(ROWS - 1):
    cells[r][0] = cells[r][COLUMNS - 1] = SOLID  # the walls
cells[13][8] = RAMP                            # a hill: up a ramp, a plateau, down again
for c in range(9, 13):
    cells[13][c] = SOLID
cells[13][13] = RAMP | FLIP_H
for c in range(16, 21):
    cells[10][c] = ONE_WAY                     # a jump-through platform
for c in range(30, 35):
    cells[6][c] = ONE_WAY                      # a high one, reached by the lift
for c in (2, 5, 14, 21, 36):
    cells[13][c] = GRASS                       # decoration: no collision

objects = [
    ('id="1" name="spawn" x="40" y="200"', '   <point/>\n'),
    ('id="2" name="lift" type="lift" x="384" y="216" width="48" height="8"',
     '   <properties>\n    <property name="type" value="kinematic"/>\n    <property name="top" type="float" value="104"/>\n   </properties>\n'),
    ('id="3" name="crate" x="288" y="176" width="16" height="16"',
     '   <properties>\n    <property name="friction" type="float" value="0.6"/>\n   </properties>\n'),
    ('id="4" name="crate" x="288" y="160" width="16" height="16"',
     '   <properties>\n    <property name="friction" type="float" value="0.6"/>\n   </properties>\n'),
]
coin = '   <properties>\n    <property name="sensor" type="bool" value="true"/>\n    <property name="type" value="static"/>\n   </properties>\n'
for i, (x, y) in enumerate([(172, 204), (292, 148), (516, 84)]):
    objects.append(('id="%d" name="coin" type="coin" x="%d" y="%d" width="8" height="8"' % (5 + i, x, y), coin))

data = ",\n".join(",".join(str(g) for g in row) for row in cells)
with open("level.tmx", "w") as f:
    f.write('<?xml version="1.0" encoding="UTF-8"?>\n')
    f.write('<map version="1.8" tiledversion="1.8.2" orientation="orthogonal" renderorder="right-down" '
            'width="%d" height="%d" tilewidth="16" tileheight="16" infinite="0" nextlayerid="3" '
            'nextobjectid="%d">\n' % (COLUMNS, ROWS, len(objects) + 1))
    f.write(' <properties>\n  <property name="gravityY" type="float" value="800"/>\n </properties>\n')
    f.write(' <tileset firstgid="1" source="tiles.tsx"/>\n')
    f.write(' <layer id="1" name="ground" width="%d" height="%d">\n  <data encoding="csv">\n%s\n</data>\n </layer>\n'
            % (COLUMNS, ROWS, data))
    f.write(' <objectgroup id="2" name="things">\n')
    for attributes, inner in objects:
        f.write('  <object %s>\n%s  </object>\n' % (attributes, inner))
    f.write(' </objectgroup>\n</map>\n')

# --- level.ldtk: the same level in LDtk's format -----------------------------------------
# An IntGrid layer whose values name their kinds (1 solid, 2 oneWay, 3 rampRight, 4
# rampLeft; grass is a picture, not in it) and an entity layer: the spawn point, the lift,
# the crates and the coins, each entity's fields its custom properties (a body's `type`
# said, as LDtk's entities are bodies only when they say so).
import json

def ldtk_field(name, kind, value):
    return {"__identifier": name, "__type": kind, "__value": value, "__tile": None, "defUid": 0, "realEditorValues": []}

kinds = {SOLID: 1, ONE_WAY: 2, RAMP: 3, RAMP | FLIP_H: 4}
grid = [kinds.get(cell, 0) for row in cells for cell in row]

def ldtk_entity(name, x, y, w, h, fields):
    return {"__identifier": name, "__grid": [x // TILE, y // TILE], "__pivot": [0, 0], "__tags": [], "__tile": None,
            "__smartColor": "#BE4A2F", "iid": "%s-%d-%d" % (name, x, y), "width": w, "height": h, "defUid": 10,
            "px": [x, y], "fieldInstances": fields}

entities = [ldtk_entity("spawn", 40, 200, 0, 0, []),
            ldtk_entity("lift", 384, 216, 48, 8, [ldtk_field("type", "String", "kinematic"), ldtk_field("top", "Float", 104)])]
for y in (176, 160):
    entities.append(ldtk_entity("crate", 288, y, 16, 16,
                                [ldtk_field("type", "String", "dynamic"), ldtk_field("friction", "Float", 0.6)]))
for x, y in [(172, 204), (292, 148), (516, 84)]:
    entities.append(ldtk_entity("coin", x, y, 8, 8, [ldtk_field("type", "String", "static"),
                                                     ldtk_field("sensor", "Bool", True)]))

def ldtk_layer(identifier, kind, uid, extra):
    layer = {"__identifier": identifier, "__type": kind, "__cWid": COLUMNS, "__cHei": ROWS, "__gridSize": TILE,
             "__opacity": 1, "__pxTotalOffsetX": 0, "__pxTotalOffsetY": 0, "__tilesetDefUid": None,
             "__tilesetRelPath": None, "iid": identifier.lower(), "levelId": 0, "layerDefUid": uid, "pxOffsetX": 0,
             "pxOffsetY": 0, "visible": True, "optionalRules": [], "intGridCsv": [], "autoLayerTiles": [],
             "seed": 1, "overrideTilesetUid": None, "gridTiles": [], "entityInstances": []}
    layer.update(extra)
    return layer

project = {
    "__header__": {"fileType": "LDtk Project JSON", "app": "LDtk", "appVersion": "1.5.3"},
    "jsonVersion": "1.5.3", "defaultGridSize": TILE, "externalLevels": False, "worldLayout": "Free",
    "defs": {"layers": [
        {"__type": "IntGrid", "identifier": "Collisions", "type": "IntGrid", "uid": 1, "gridSize": TILE,
         "intGridValues": [{"value": 1, "identifier": "solid", "color": "#6E4E34"},
                           {"value": 2, "identifier": "oneWay", "color": "#A07846"},
                           {"value": 3, "identifier": "rampRight", "color": "#6E4E34"},
                           {"value": 4, "identifier": "rampLeft", "color": "#6E4E34"}]},
        {"__type": "Entities", "identifier": "Entities", "type": "Entities", "uid": 2, "gridSize": TILE}],
        "entities": [], "tilesets": [], "enums": [], "externalEnums": [], "levelFields": []},
    "levels": [{"identifier": "Level_0", "iid": "level-0", "uid": 0, "worldX": 0, "worldY": 0,
                "pxWid": COLUMNS * TILE, "pxHei": ROWS * TILE, "__bgColor": "#40465B", "externalRelPath": None,
                "fieldInstances": [ldtk_field("gravityY", "Float", 800)],
                "layerInstances": [ldtk_layer("Entities", "Entities", 2, {"entityInstances": entities}),
                                   ldtk_layer("Collisions", "IntGrid", 1, {"intGridCsv": grid})]}],
}
with open("level.ldtk", "w") as f:
    json.dump(project, f, indent=1)
