{{ 'Hello'.lower() }} {{ 'Hello'.upper() }} [{{ '  x  '.strip() }}] [{{ 'xxaxx'.strip('x') }}] [{{ '  x '.lstrip() }}] [{{ ' x  '.rstrip() }}]
{{ 'abc'.startswith('ab') }} {{ 'abc'.endswith('bc') }} {{ 'abc'.startswith(('x', 'a')) }} {{ 'a-b-c'.replace('-', '') }} {{ 'aaa'.replace('a', 'b', 1) }}
{{ 'a,b,,c'.split(',') }} {{ '  a  b c '.split() }} {{ 'a b c'.split(none, 1) }} {{ 'a,b,c'.rsplit(',', 1) }} {{ ' a b '.rsplit() }}
{{ '-'.join(['a', 'b']) }} {{ ''.join('xyz') }} {{ 'hello world'.title() }} {{ 'hello'.capitalize() }} {{ 'HeLLo'.swapcase() }}
{{ 'banana'.count('an') }} {{ 'banana'.find('n') }} {{ 'banana'.rfind('n') }} {{ 'banana'.find('z') }} {{ 'éa'.find('a') }}
{{ '42'.isdigit() }} {{ 'ab'.isalpha() }} {{ 'a1'.isalnum() }} {{ '  '.isspace() }} {{ 'abc'.islower() }} {{ 'ABC'.isupper() }}
[{{ 'ab'.ljust(5, '.') }}] [{{ 'ab'.rjust(5) }}] [{{ 'ab'.center(6, '*') }}] {{ '42'.zfill(5) }} {{ '-42'.zfill(5) }} {{ 'a\nb\r\nc'.splitlines() }}
