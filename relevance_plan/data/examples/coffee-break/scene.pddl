; The snack table of a conference break (the paper's demonstration, Section VI):
; coffee, cups, milk, utensils and desserts; nobody is being served yet.
(define (problem coffee-break)
  (:domain coffee)
  (:objects
    kitchen_counter_1 serving_table_1 - surface
    cabinet_1 - container
    cold_brew_coffee_1 - coffee-source
    paper_cup_1 plastic_cup_1 - cup
    whole_milk_1 creamer_1 - whitener
    stir_stick_1 - stirrer
    sugar_packet_1 - sweetener
    napkin_1 - napkin
    tea_bag_1 - tea
    water_bottle_1 - drink
    donut_1 - food
    cake_plate_1 - plate
  )
  (:init
    (robot-at kitchen_counter_1)
    (hand-empty)
    (accessible kitchen_counter_1)
    (accessible serving_table_1)
    (at cold_brew_coffee_1 kitchen_counter_1) (on-base cold_brew_coffee_1) (clear cold_brew_coffee_1)
    (at plastic_cup_1 kitchen_counter_1) (on-base plastic_cup_1) (clear plastic_cup_1) (empty plastic_cup_1)
    (at paper_cup_1 serving_table_1) (on-base paper_cup_1) (clear paper_cup_1) (empty paper_cup_1)
    (at whole_milk_1 kitchen_counter_1) (on-base whole_milk_1) (clear whole_milk_1)
    (at creamer_1 serving_table_1) (on-base creamer_1) (clear creamer_1)
    (at stir_stick_1 serving_table_1) (on-base stir_stick_1) (clear stir_stick_1)
    (at sugar_packet_1 serving_table_1) (on-base sugar_packet_1) (clear sugar_packet_1)
    (at napkin_1 serving_table_1) (on-base napkin_1) (clear napkin_1)
    (at tea_bag_1 serving_table_1) (on-base tea_bag_1) (clear tea_bag_1)
    (at water_bottle_1 serving_table_1) (on-base water_bottle_1) (clear water_bottle_1)
    (at donut_1 serving_table_1) (on-base donut_1) (clear donut_1)
    (at cake_plate_1 cabinet_1) (on-base cake_plate_1) (clear cake_plate_1)
  )
  (:goal (and))
)
