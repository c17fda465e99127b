#!/usr/bin/env python3
# Writes level.ldtk and level_1.ldtkl, the LDtk test project of test_ldtk.cpp (which says
# what they hold): LDtk's JSON structure (1.x), with the fields jostle reads and a few it
# skips, as LDtk saves them. Run it here to make them again: python3 make_ldtk.py
import json

def field(name, kind, value):
    return {"__identifier": name, "__type": kind, "__value": value, "__tile": None, "defUid": 0, "realEditorValues": []}

def entity(name, px, pivot, w, h, fields):
    return {"__identifier": name, "__grid": [px[0] // 16, px[1] // 16], "__pivot": pivot, "__tags": [], "__tile": None,
            "__smartColor": "#FFFFFF", "iid": name.lower(), "width": w, "height": h, "defUid": 2, "px": px,
            "fieldInstances": fields}

def layer(identifier, kind, uid, extra):
    out = {"__identifier": identifier, "__type": kind, "__cWid": 8, "__cHei": 4, "__gridSize": 16, "__opacity": 1,
           "__pxTotalOffsetX": 0, "__pxTotalOffsetY": 0, "__tilesetDefUid": None, "__tilesetRelPath": None,
           "iid": identifier.lower(), "levelId": 0, "layerDefUid": uid, "pxOffsetX": 0, "pxOffsetY": 0,
           "visible": True, "optionalRules": [], "intGridCsv": [], "autoLayerTiles": [], "seed": 1,
           "overrideTilesetUid": None, "gridTiles": [], "entityInstances": []}
    out.update(extra)
    return out

grid = [0] * 8 + [0, 0, 2, 2, 0, 0, 0, 4] + [0, 0, 0, 0, 0, 3, 1, 0] + [1] * 8
entities = [
    entity("Player", [8, 48], [0.5, 1], 12, 16, []),
    entity("Crate", [40, 16], [0.5, 1], 16, 16, [field("type", "String", "dynamic"), field("friction", "Float", 0.25)]),
    entity("Coin", [116, 44], [0.5, 0.5], 8, 8,
           [field("type", "String", "static"), field("sensor", "Bool", True), field("value", "Int", 5)]),
]
project = {
    "__header__": {"fileType": "LDtk Project JSON", "app": "LDtk", "appVersion": "1.5.3"},
    "jsonVersion": "1.5.3", "defaultGridSize": 16, "externalLevels": False, "worldLayout": "Free",
    "defs": {"layers": [
        {"__type": "IntGrid", "identifier": "Collisions", "type": "IntGrid", "uid": 1, "gridSize": 16,
         "intGridValues": [{"value": 1, "identifier": "solid", "color": "#000000"},
                           {"value": 2, "identifier": "oneWay", "color": "#884400"},
                           {"value": 3, "identifier": "rampRight", "color": "#444444"},
                           {"value": 4, "identifier": "water", "color": "#0000FF"}]},
        {"__type": "Entities", "identifier": "Entities", "type": "Entities", "uid": 2, "gridSize": 16}],
        "entities": [], "tilesets": [], "enums": [], "externalEnums": [], "levelFields": []},
    "levels": [
        {"identifier": "Level_0", "iid": "level-0", "uid": 0, "worldX": 0, "worldY": 0, "pxWid": 128, "pxHei": 64,
         "__bgColor": "#40465B", "externalRelPath": None,
         "fieldInstances": [field("gravityY", "Float", 800)],
         "layerInstances": [layer("Entities", "Entities", 2, {"entityInstances": entities}),
                            layer("Collisions", "IntGrid", 1, {"intGridCsv": grid})]},
        {"identifier": "Level_1", "iid": "level-1", "uid": 1, "worldX": 128, "worldY": 0, "pxWid": 128, "pxHei": 64,
         "externalRelPath": "level_1.ldtkl", "fieldInstances": [], "layerInstances": None},
    ],
}
with open("level.ldtk", "w") as f:
    json.dump(project, f, indent=1)
separate = {"identifier": "Level_1", "iid": "level-1", "uid": 1, "worldX": 128, "worldY": 0, "pxWid": 128,
            "pxHei": 64, "fieldInstances": [],
            "layerInstances": [layer("Collisions", "IntGrid", 1, {"intGridCsv": [1] * 32})]}
with open("level_1.ldtkl", "w") as f:
    json.dump(separate, f, indent=1)
