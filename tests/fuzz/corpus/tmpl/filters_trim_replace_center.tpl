[{{ '  both  ' | trim }}] [{{ 'xxhixx' | trim('x') }}] [{{ '\u3000wide\t' | trim }}]
{{ 'a-b-c' | replace('-', '+') }} {{ 'aaaa' | replace('a', 'b', 2) }} {{ 'abc' | replace('', '.') }} {{ 12345 | replace(3, 'x') }}
[{{ 'mid' | center(9) }}] [{{ 'mid' | center(8) }}] [{{ 'ab' | center(7) }}] [{{ 'toolong' | center(3) }}]
