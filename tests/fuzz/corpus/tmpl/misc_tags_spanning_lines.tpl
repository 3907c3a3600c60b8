{% if
    true
%}yes{%
endif %} {{
  1 +
  2
}}
