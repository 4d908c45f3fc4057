"""The cycle's and the dynamics sheets' words, in both languages, and the units' names."""

from __future__ import annotations

from drawings.paper.i18n import lookup

WORDS: dict[str, tuple[str, str]] = {
    "diagrams": ("Кинематические диаграммы", "Kinematic diagrams"),
    "dynamics": ("Динамика машины. Маховик", "Machine dynamics. Flywheel"),
    "s": ("Диаграмма перемещений", "Displacement diagram"),
    "v": ("Диаграмма скоростей", "Velocity diagram"),
    "a": ("Диаграмма ускорений", "Acceleration diagram"),
    "chords": ("метод хорд", "chord method"),
    "tangents": ("метод касательных", "tangent method"),
    "exact_thin": ("тонкая штриховая — точная кривая", "thin dashed: exact curve"),
    "error": ("погрешность", "error"),
    "errors": ("Погрешность графических диаграмм, % размаха", "Error of the graphical diagrams, % of range"),
    "M": ("Приведённый момент сил M_пр(φ)", "Reduced moment of forces M_pr(φ)"),
    "A": ("Работы A_c(φ), A_д(φ)", "Work A_c(φ), A_d(φ)"),
    "T": ("Изменение кинетической энергии ΔT(φ)", "Change of kinetic energy ΔT(φ)"),
    "I": ("Приведённый момент инерции I_пр(φ)", "Reduced moment of inertia I_pr(φ)"),
    "W": ("Диаграмма энергомасс (Виттенбауэр)", "Energy–mass diagram (Wittenbauer)"),
    "w": ("Угловая скорость кривошипа ω(φ)", "Angular velocity of the crank ω(φ)"),
    "fly": ("Маховик", "Flywheel"),
    "sign": ("M_пр > 0: нагрузки движут кривошип", "M_pr > 0: the loads drive the crank"),
    "method": ("Метод", "Method"),
    "inertia": ("I_м, кг·м²", "I_fw, kg·m²"),
    "achieved": ("δ достигнутое", "δ achieved"),
    "diff": ("Δ к точному, %", "vs exact, %"),
    "graphical": ("Виттенбауэр", "Wittenbauer"),
    "merkalov": ("Мерцалов", "Merkalov"),
    "exact": ("точно", "exact"),
    "position": ("№ положения", "Position"),
    "phi": ("φ, °", "φ, deg"),
    "analogues": ("Аналоги скоростей", "Velocity analogues"),
    "Ipr": ("Приведённый момент инерции, кг·м²", "Reduced moment of inertia, kg·m²"),
    "Mpr": ("Приведённый момент сил, Н·м", "Reduced moment of forces, N·m"),
    "plans": ("Планы по положениям", "Plans over the positions"),
    "ordinates": ("Ординаты диаграмм по положениям:", "Ordinates of the diagrams over the positions:"),
    "energy": ("Работы и кинетическая энергия, Дж", "Work and kinetic energy, J"),
    "with_graphical": ("с маховиком по Виттенбауэру", "with the Wittenbauer flywheel"),
    "with_exact": ("с точным маховиком", "with the exact flywheel"),
    "indicator": ("Индикаторная диаграмма", "Indicator diagram"),
    "intake": ("впуск", "intake"),
    "compression": ("сжатие", "compression"),
    "expansion": ("расширение", "expansion"),
    "exhaust": ("выпуск", "exhaust"),
    "down": ("ход к валу", "toward the crank"),
    "up": ("ход от вала", "away from the crank"),
    "fires": ("воспламенение при φ", "ignition at φ"),
}


UNITS = {"N*m": ("Н·м", "N·m"), "kg*m^2": ("кг·м²", "kg·m²"), "m": ("м", "m"), "mm": ("мм", "mm"),
          "J": ("Дж", "J"), "N": ("Н", "N"), "m/s": ("м/с", "m/s"), "m/s^2": ("м/с²", "m/s²"),
          "rad": ("рад", "rad"),
         "rad/s": ("рад/с", "rad/s"), "rad/s^2": ("рад/с²", "rad/s²"), "deg": ("°", "°")}


tr = lookup(WORDS)
