{% set s = 'x' * 100000000 %}{{ (s ~ s ~ s) | length }}
