start
    {% for x in xs %}
    item {{ x }}
    {% endfor %}
	{% if true %}
  tabbed
	{% endif %}
end
%%context
xs: [1, 2]
