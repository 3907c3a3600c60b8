{% set l = [3, 1, 2] %}{% do l.append(4) %}{% do l.insert(0, 0) %}{{ l }} {{ l.index(2) }} {{ l.count(1) }} {{ l.pop() }} {{ l.pop(0) }} {{ l }}
{% do l.remove(1) %}{% do l.reverse() %}{{ l }} {% do l.sort() %}{{ l }} {% set c = l.copy() %}{% do c.clear() %}{{ l }} {{ c }}
{{ l.append(9) }} {{ l }}
