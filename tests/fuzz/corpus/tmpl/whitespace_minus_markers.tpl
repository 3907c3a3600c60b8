<
    {%- for x in xs -%}
    [{{ x }}]
    {%- endfor -%}
    >
{{- ' tight ' -}}
  |   {{- 'a' }}   {{ 'b' -}}   |
{#- comment -#}
  after
%%context
xs: [a, b, c]
