"""The pool of 200 task-irrelevant kitchenware kinds the generator draws from.

Each entry is ``(kind_name, pddl_type)``.  The PDDL type is one of the
general kitchenware types that both domains declare (``KITCHENWARE_TYPES``),
so every distractor is legal in either world.  Nothing here can play a task
role or be an optional extra in either world: no cups, mugs, glasses to
drink from, bowls, spoons, stirrers, milk or creamer, coffee, tea, cereal,
sweeteners, fruit, napkins or paper towels, ice holders, or drinks.
(``tea_towel`` is a dish cloth: the name is a deliberate near-miss.)

Kind names are lowercase words joined by underscores, without digits; an
object of a kind is named ``<kind>_<index>`` (``dinner_plate_3``).
"""

from __future__ import annotations

KITCHENWARE_TYPES: tuple[str, ...] = (
    "plate",
    "cookware",
    "utensil",
    "cutlery",
    "glassware",
    "board",
    "tray",
    "jar",
    "linen",
    "appliance",
    "food",
    "cleaning",
)

_BY_TYPE: dict[str, tuple[str, ...]] = {
    "plate": (
        "dinner_plate", "salad_plate", "side_plate", "dessert_plate", "charger_plate",
        "bread_plate", "pizza_plate", "cake_plate", "appetizer_plate", "divided_plate",
        "paper_plate", "serving_platter", "oval_platter", "fish_platter",
    ),
    "cookware": (
        "saucepan", "frying_pan", "skillet", "stockpot", "dutch_oven", "wok", "saute_pan",
        "grill_pan", "roasting_pan", "baking_sheet", "muffin_tin", "loaf_pan", "cake_pan",
        "springform_pan", "pie_dish", "casserole_dish", "steamer_basket", "double_boiler",
        "crepe_pan", "paella_pan", "tagine", "bundt_pan", "ramekin", "gratin_dish",
        "pizza_stone", "tart_pan", "baking_dish", "cooling_rack",
    ),
    "utensil": (
        "whisk", "ladle", "spatula", "tongs", "grater", "colander", "rolling_pin",
        "potato_masher", "can_opener", "bottle_opener", "corkscrew", "vegetable_peeler",
        "garlic_press", "pastry_brush", "sieve", "funnel", "kitchen_scissors",
        "meat_thermometer", "pizza_cutter", "salad_spinner", "mandoline", "zester",
        "fish_slice", "meat_tenderizer", "nutcracker", "pastry_cutter",
        "cookie_cutter", "piping_bag", "flour_sifter", "pie_server", "pepper_mill",
        "mortar_and_pestle",
    ),
    "cutlery": (
        "dinner_knife", "steak_knife", "butter_knife", "bread_knife", "chef_knife",
        "paring_knife", "carving_knife", "cleaver", "santoku_knife", "boning_knife",
        "fillet_knife", "cheese_knife", "dinner_fork", "salad_fork", "carving_fork",
        "oyster_fork",
    ),
    "glassware": (
        "wine_glass", "champagne_flute", "martini_glass", "brandy_snifter", "margarita_glass",
        "decanter", "oil_cruet", "cake_stand", "glass_cloche", "hurricane_glass",
        "glass_vase", "trifle_dish",
    ),
    "board": (
        "cutting_board", "cheese_board", "bread_board", "chopping_block", "carving_board",
        "pastry_board", "charcuterie_board", "serving_board", "pizza_peel", "trivet",
        "knife_block",
    ),
    "tray": (
        "serving_tray", "baking_tray", "cutlery_tray", "butler_tray", "bed_tray",
        "oven_tray", "cafeteria_tray", "appetizer_tray", "drip_tray",
    ),
    "jar": (
        "mason_jar", "spice_jar", "pickle_jar", "cookie_jar", "flour_canister", "pasta_jar",
        "olive_jar", "storage_jar", "herb_jar", "rice_canister", "utensil_crock",
        "salt_shaker", "fermentation_crock",
    ),
    "linen": (
        "tablecloth", "placemat", "oven_mitt", "pot_holder", "apron", "tea_towel",
        "dish_towel", "table_runner", "bread_cloth", "cheesecloth",
    ),
    "appliance": (
        "toaster", "blender", "microwave", "food_processor", "stand_mixer", "hand_mixer",
        "rice_cooker", "slow_cooker", "waffle_iron", "sandwich_press", "air_fryer",
        "toaster_oven", "bread_maker", "deep_fryer", "electric_griddle", "food_dehydrator",
        "sous_vide_cooker", "popcorn_maker", "immersion_blender", "kitchen_scale",
    ),
    "food": (
        "bread_loaf", "baguette", "olive_oil", "vinegar", "soy_sauce", "ketchup", "mustard",
        "rice_bag", "flour_bag", "pasta_packet", "canned_beans", "tuna_can",
        "potato", "onion", "garlic", "carrot", "butter", "cheese_block", "egg_carton",
    ),
    "cleaning": (
        "sponge", "dish_soap", "scrub_brush", "dish_brush", "steel_wool", "dish_rack",
        "trash_can", "recycling_bin", "broom", "dustpan", "mop", "spray_bottle",
        "rubber_gloves", "scouring_pad", "bottle_brush", "compost_bin",
    ),
}

CATALOG: tuple[tuple[str, str], ...] = tuple(
    (kind, type_name) for type_name, kinds in _BY_TYPE.items() for kind in kinds
)
"""Every distractor kind with its PDDL type, in a fixed order (the generator
samples from this order, so changing it changes every generated suite)."""

CATALOG_TYPES: dict[str, str] = dict(CATALOG)
"""Kind name -> PDDL type."""

if len(CATALOG) != 200 or len(CATALOG_TYPES) != 200:  # pragma: no cover - guards edits
    raise RuntimeError(f"the distractor catalog must hold 200 distinct kinds, not {len(CATALOG_TYPES)}")
